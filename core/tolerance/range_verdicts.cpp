// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tolerance/range_verdicts.h"

#include "core/project/operations.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <functional>

namespace tolturn {

namespace {

struct RangeVerdicts {
    Q_DECLARE_TR_FUNCTIONS(RangeVerdicts)
};

// The search for a required stiffness: a grid of half decades from 1 N/µm to 10⁶ N/µm, then
// bisection in log K inside the half decade where the verdict changes: 9 halvings of a factor
// sqrt(10) leave a bracket of 0.23 %.
constexpr double kSearchLow_N_per_mm = 1.0e3;
constexpr int kGridPoints = 13;
constexpr int kBisections = 9;

double gridStiffness(int i)
{
    return kSearchLow_N_per_mm * std::pow(10.0, 0.5 * i);
}

bool passes(const ToleranceEvaluation &e)
{
    return e.verdict == Verdict::PassesAsProgrammed;
}

// One constant offset of the programmed size that holds a size at both ends of the range, where
// one end or both do not hold as programmed: the predicted sizes of both ends (each about the same
// programmed size) must fit in the zone together, and the offset centres them. A part in the chuck
// alone moves by F/K (withChuckTranslation), so between the ends its sizes stay between theirs;
// with a tailstock the ends are taken to bound the sizes between them, which is not proven.
std::optional<double> offsetForBothEnds(const ToleranceEvaluation &compliant, const ToleranceEvaluation &stiff)
{
    const auto sized = [](const ToleranceEvaluation &e) {
        return (e.verdict == Verdict::PassesAsProgrammed || e.verdict == Verdict::PassesAfterOffset) &&
               e.predictedMax_um && e.predictedMin_um && e.limit_um;
    };
    if (!sized(compliant) || !sized(stiff))
        return std::nullopt;
    // The end that needs an offset tells the programmed size: its offset centres its sizes on it.
    const ToleranceEvaluation &offset = compliant.offset_um ? compliant : stiff;
    if (!offset.offset_um)
        return std::nullopt; // both hold as programmed
    const double largest = std::max(*compliant.predictedMax_um, *stiff.predictedMax_um);
    const double smallest = std::min(*compliant.predictedMin_um, *stiff.predictedMin_um);
    if (largest - smallest > *compliant.limit_um)
        return std::nullopt;
    const double programmed = *offset.offset_um + 0.5 * (*offset.predictedMax_um + *offset.predictedMin_um);
    return programmed - 0.5 * (largest + smallest);
}

bool decided(const ToleranceEvaluation &e)
{
    return e.verdict != Verdict::NotPredicted && e.verdict != Verdict::CannotEvaluate;
}

using VerdictsAt = std::function<std::vector<ToleranceEvaluation>(double stiffness_N_per_mm)>;

// The smallest stiffness with which each tolerance passes as programmed, and the first stiffer grid
// point where it fails again, if any.
std::vector<RequiredStiffness> searchRequired(const VerdictsAt &verdictsAt, std::size_t count)
{
    std::vector<int> firstPassing(count, -1);
    std::vector<int> failsAgain(count, -1);
    for (int i = 0; i < kGridPoints; ++i) {
        const std::vector<ToleranceEvaluation> v = verdictsAt(gridStiffness(i));
        for (std::size_t t = 0; t < count && t < v.size(); ++t) {
            if (firstPassing[t] < 0 && passes(v[t]))
                firstPassing[t] = i;
            else if (firstPassing[t] >= 0 && failsAgain[t] < 0 && !passes(v[t]))
                failsAgain[t] = i;
        }
    }
    std::vector<RequiredStiffness> out(count);
    for (std::size_t t = 0; t < count; ++t) {
        if (firstPassing[t] < 0) {
            out[t].kind = RequiredStiffness::Kind::NotReachable;
            continue;
        }
        if (firstPassing[t] == 0 && failsAgain[t] < 0) {
            out[t].kind = RequiredStiffness::Kind::AnyStiffness;
            out[t].value_N_per_mm = kSearchLow_N_per_mm;
            continue;
        }
        if (firstPassing[t] == 0) { // passes at the bottom of the search, fails higher up
            out[t].kind = RequiredStiffness::Kind::Window;
            out[t].value_N_per_mm = kSearchLow_N_per_mm;
            out[t].upper_N_per_mm = gridStiffness(failsAgain[t]);
            continue;
        }
        double failing = std::log(gridStiffness(firstPassing[t] - 1));
        double passing = std::log(gridStiffness(firstPassing[t]));
        for (int k = 0; k < kBisections; ++k) {
            const double mid = 0.5 * (failing + passing);
            const std::vector<ToleranceEvaluation> v = verdictsAt(std::exp(mid));
            (t < v.size() && passes(v[t]) ? passing : failing) = mid;
        }
        out[t].kind = failsAgain[t] < 0 ? RequiredStiffness::Kind::Found : RequiredStiffness::Kind::Window;
        out[t].value_N_per_mm = std::exp(passing);
        if (failsAgain[t] >= 0)
            out[t].upper_N_per_mm = gridStiffness(failsAgain[t]);
    }
    return out;
}

std::vector<ToleranceEvaluation> verdictsWith(const Project &project, const TurningInputs &inputs,
                                              const DeviationOptions &options, const ProgramTargets &targets)
{
    return evaluateTolerances(project, deviationFor(project.part, inputs, options), EvaluationDetail::ValuesOnly,
                              &targets);
}

// A part held by the chuck alone is statically determinate: the family's spring K at the chuck
// face (held against tilt) moves it as a rigid body by F/K, radially F_r/K and tangentially F_t/K,
// whatever else deflects; faces do not turn with it. So the deviation at any K follows from one
// evaluation exactly, without solving the beam again.
DeviationResult withChuckTranslation(DeviationResult d, double k_N_per_mm)
{
    for (FeatureDeviation &feature : d.features) {
        const CuttingForces &f = d.inputs->forcesOn(feature.side); // a bore is cut by the boring bar's insert
        for (Station &st : feature.stations) {
            st.radial.spindleChuck_mm = f.radial_N / k_N_per_mm;
            st.tangential.spindleChuck_mm = f.tangential_N / k_N_per_mm;
            st.radiusError_mm = radiusError_mm(st.nominalRadius_mm, st.radial.total_mm(), st.tangential.total_mm(),
                                               feature.side == ContourSide::Outer);
        }
    }
    return d;
}

bool hasRange(const SupportStiffnessUsed &s)
{
    return s.basis == SupportBasis::RangeEnd;
}

QString perMicrometre(double k_N_per_mm)
{
    return formatNumber(std::round(k_N_per_mm / 100.0) / 10.0);
}

QString sourceShort(const DataLibrary &data, const StiffnessRange &r)
{
    return data.sourceText(r.compliant_N_per_mm.source).section(QLatin1Char(','), 0, 1);
}

} // namespace

RangeEvaluation evaluateOverStiffnessRange(const Project &project, const DataLibrary &data,
                                           const DeviationOptions &options)
{
    RangeEvaluation out;
    DeviationOptions compliant = options;
    compliant.stiffnessEnd = StiffnessEnd::Compliant;
    compliant.chuckStiffness_N_per_mm.reset();
    compliant.tailstockStiffness_N_per_mm.reset();
    out.compliant = computeDeviation(project, data, compliant);
    if (!out.compliant.inputs)
        return out;
    const TurningInputs &in = *out.compliant.inputs;
    out.machineIsRange = hasRange(in.chuck) || hasRange(in.tailstock);
    out.thermalTakenAsZero = !options.workpieceOnly && !in.thermal;
    out.someSupportRigid = in.chuck.basis == SupportBasis::RigidNoData ||
                           in.tailstock.basis == SupportBasis::RigidNoData ||
                           in.headstockCentre.basis == SupportBasis::RigidNoData;
    const std::vector<ToleranceEvaluation> atCompliant = evaluateTolerances(project, out.compliant);
    std::vector<ToleranceEvaluation> atStiff;
    if (out.machineIsRange) {
        DeviationOptions stiff = compliant;
        stiff.stiffnessEnd = StiffnessEnd::Stiff;
        out.stiff = computeDeviation(project, data, stiff);
        atStiff = evaluateTolerances(project, *out.stiff);
    }
    const std::size_t n = atCompliant.size();
    std::vector<RequiredStiffness> chuck;
    std::vector<RequiredStiffness> tailstock;
    // The project is resolved once; the searches vary only the support they are about.
    const ClampingMethod method = project.clamping.method;
    const ProgramTargets targets = programTargets(project);
    if (holdsOneEndOnly(method) && !options.workpieceOnly) {
        const DeviationResult base = deviationFor(project.part, withChuckStiffness(in, gridStiffness(0)), compliant);
        chuck = searchRequired(
            [&](double k) {
                return evaluateTolerances(project, withChuckTranslation(base, k), EvaluationDetail::ValuesOnly,
                                          &targets);
            },
            n);
    } else if (method == ClampingMethod::ChuckTailstock && !options.workpieceOnly) {
        chuck = searchRequired(
            [&](double k) { return verdictsWith(project, withChuckStiffness(in, k), compliant, targets); }, n);
    }
    if (!holdsOneEndOnly(method) && !options.workpieceOnly)
        tailstock = searchRequired(
            [&](double k) { return verdictsWith(project, withTailstockStiffness(in, k, method), compliant, targets); },
            n);
    for (std::size_t i = 0; i < n; ++i) {
        ToleranceRangeEvaluation e;
        e.compliant = atCompliant[i];
        if (i < atStiff.size())
            e.stiff = atStiff[i];
        if (i < chuck.size() && decided(e.compliant))
            e.chuck = chuck[i];
        e.collet = in.collet;
        if (i < tailstock.size() && decided(e.compliant))
            e.tailstock = tailstock[i];
        if (!decided(e.compliant))
            e.range = RangeVerdict::NotDecided;
        else if (!e.stiff)
            e.range = RangeVerdict::NoRange;
        else if (passes(e.compliant) && passes(*e.stiff))
            e.range = RangeVerdict::PassesOnAnyMachine;
        else {
            e.offsetOnAnyMachine_um = offsetForBothEnds(e.compliant, *e.stiff);
            if (passes(e.compliant))
                e.range = RangeVerdict::PassesOnPartOfRange;
            else if (passes(*e.stiff))
                e.range = RangeVerdict::PassesIfStiffer;
            else
                e.range = e.offsetOnAnyMachine_um ? RangeVerdict::PassesAfterOffsetOnAnyMachine
                                                  : RangeVerdict::FailsEvenOnStiffest;
        }
        out.tolerances.push_back(e);
    }
    return out;
}

void addReclampingNotes(const Project &project, RangeEvaluation &range, const DataLibrary &data)
{
    for (ToleranceRangeEvaluation &e : range.tolerances) {
        const auto t = std::find_if(project.tolerances.begin(), project.tolerances.end(),
                                    [&e](const Tolerance &x) { return x.id == e.compliant.toleranceId; });
        if (t == project.tolerances.end())
            continue;
        if (!spansOperations(project, *t))
            continue;
        const auto error = reclampingError(project, *t, data);
        if (!error) { // a length between faces of two set-ups: where the part sits axially again
            e.compliant.reason.prepend(
                RangeVerdicts::tr("spans set-ups: its error from clamping the part again (where it sits "
                                  "axially in the other set-up) is not known and not in this verdict. "));
            continue;
        }
        const bool predicted = e.compliant.value_um.has_value() && e.compliant.limit_um.has_value();
        const std::optional<double> value = predicted ? e.compliant.value_um : std::optional<double>(0.0);
        const std::optional<double> limit = predicted ? e.compliant.limit_um : t->zone_um;
        const QString text = reclampingText(project, *t, *error, value, limit);
        e.compliant.reason = e.compliant.reason.isEmpty() ? text : text + QStringLiteral(". ") + e.compliant.reason;
    }
}

QString rangeVerdictKeyword(RangeVerdict verdict)
{
    switch (verdict) {
    case RangeVerdict::PassesOnAnyMachine:
        return QStringLiteral("passes_on_any_machine");
    case RangeVerdict::PassesIfStiffer:
        return QStringLiteral("passes_if_stiffer");
    case RangeVerdict::PassesOnPartOfRange:
        return QStringLiteral("passes_on_part_of_range");
    case RangeVerdict::PassesAfterOffsetOnAnyMachine:
        return QStringLiteral("passes_after_offset_on_any_machine");
    case RangeVerdict::FailsEvenOnStiffest:
        return QStringLiteral("fails_even_on_stiffest");
    case RangeVerdict::NotFinished:
        return QStringLiteral("not_finished");
    case RangeVerdict::NoRange:
        return QStringLiteral("no_range");
    case RangeVerdict::NotDecided:
        return QStringLiteral("not_decided");
    }
    return {};
}

QString requiredStiffnessText(const RequiredStiffness &r)
{
    switch (r.kind) {
    case RequiredStiffness::Kind::Found:
        return RangeVerdicts::tr("≥ %1 N/µm").arg(perMicrometre(r.value_N_per_mm));
    case RequiredStiffness::Kind::Window:
        return RangeVerdicts::tr("%1–%2 N/µm only")
            .arg(perMicrometre(r.value_N_per_mm), perMicrometre(r.upper_N_per_mm));
    case RequiredStiffness::Kind::AnyStiffness:
        return RangeVerdicts::tr("any");
    case RequiredStiffness::Kind::NotReachable:
        return RangeVerdicts::tr("not reachable");
    }
    return {};
}

// A verdict that holds only on part of the range, and what one offset would do on all of it.
QString withOffsetOnAnyMachine(const QString &verdict, const ToleranceRangeEvaluation &e)
{
    if (!e.offsetOnAnyMachine_um)
        return verdict;
    return RangeVerdicts::tr("%1; an offset of %2 µm on the diameter holds it on any machine in the range")
        .arg(verdict, QString::number(*e.offsetOnAnyMachine_um, 'f', 1));
}

QString rangeVerdictText(const ToleranceRangeEvaluation &e)
{
    switch (e.range) {
    case RangeVerdict::PassesOnAnyMachine:
        return RangeVerdicts::tr("passes on any machine in the range");
    case RangeVerdict::PassesIfStiffer: {
        const std::optional<RequiredStiffness> &r =
            e.chuck && e.chuck->kind == RequiredStiffness::Kind::Found ? e.chuck : e.tailstock;
        if (r && r->kind == RequiredStiffness::Kind::Found)
            return withOffsetOnAnyMachine(RangeVerdicts::tr("passes only if the machine is stiffer than %1 N/µm")
                                              .arg(perMicrometre(r->value_N_per_mm)),
                                          e);
        return withOffsetOnAnyMachine(RangeVerdicts::tr("passes only on the stiffer machines of the range"), e);
    }
    case RangeVerdict::PassesOnPartOfRange:
        return withOffsetOnAnyMachine(
            RangeVerdicts::tr("passes on the compliant machines of the range, not on the stiffest"), e);
    case RangeVerdict::PassesAfterOffsetOnAnyMachine:
        return RangeVerdicts::tr("fails as programmed; an offset of %1 µm on the diameter holds it on any machine "
                                 "in the range")
            .arg(QString::number(e.offsetOnAnyMachine_um.value_or(0.0), 'f', 1));
    case RangeVerdict::FailsEvenOnStiffest:
        return RangeVerdicts::tr("fails as programmed even on the stiffest machine of the range");
    case RangeVerdict::NotFinished:
        return RangeVerdicts::tr("not finished by the program: %1").arg(e.unfinished.join(QStringLiteral(", ")));
    case RangeVerdict::NoRange:
    case RangeVerdict::NotDecided:
        return verdictName(e.compliant.verdict);
    }
    return {};
}

QString machineAssumptionText(const RangeEvaluation &r, const DataLibrary &data)
{
    if (!r.compliant.inputs)
        return {};
    const TurningInputs &in = *r.compliant.inputs;
    QStringList parts;
    if (in.chuck.basis == SupportBasis::RangeEnd && in.chuck.range)
        parts << RangeVerdicts::tr("chuck not measured: radial stiffness %1–%2 N/µm at the chuck face (%3), results "
                                   "at both ends, verdicts and plans at the compliant end")
                     .arg(perMicrometre(in.chuck.range->compliant_N_per_mm.value),
                          perMicrometre(in.chuck.range->stiff_N_per_mm.value), sourceShort(data, *in.chuck.range));
    else if (in.chuck.basis == SupportBasis::Measured)
        parts << RangeVerdicts::tr("spindle–chuck as measured");
    else if (in.chuck.basis == SupportBasis::RigidNoData && in.collet)
        parts << RangeVerdicts::tr("collet not measured and no published stiffness: taken as rigid (optimistic); "
                                   "see the stiffness each tolerance needs");
    else if (in.chuck.basis == SupportBasis::RigidNoData)
        parts << RangeVerdicts::tr("chuck neither measured nor published: taken as rigid (optimistic)");
    if (in.tailstock.basis == SupportBasis::RigidNoData)
        parts << RangeVerdicts::tr("tailstock and centres not measured and no published stiffness: taken as rigid "
                                   "(optimistic); see the stiffness each tolerance needs");
    else if (in.tailstock.basis == SupportBasis::Measured)
        parts << RangeVerdicts::tr("tailstock as measured");
    if (in.headstockCentre.basis == SupportBasis::RigidNoData && in.tailstock.basis != SupportBasis::RigidNoData)
        parts << RangeVerdicts::tr("headstock centre not measured and no published stiffness: taken as rigid "
                                   "(optimistic)");
    // Zero drift is an ideal too: said here, where the verdicts are read, not only in the notes.
    if (r.thermalTakenAsZero)
        parts << RangeVerdicts::tr("thermal drift not measured: taken as zero (optimistic)");
    return parts.join(QStringLiteral("; "));
}

} // namespace tolturn
