// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/measured_residuals.h"

#include "core/deviation/deviation_model.h"
#include "core/io/project_json.h"
#include "core/project/operations.h"
#include "core/tolerance/target_contour.h"

#include <QCoreApplication>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace tolturn {

namespace {

struct MeasuredResiduals {
    Q_DECLARE_TR_FUNCTIONS(MeasuredResiduals)
};

constexpr int kBackfittingPasses = 4;

// The predicted radius error on a feature at z, linear between its stations.
std::optional<double> physicsAt(const DeviationResult &d, const QString &featureId, double z)
{
    for (const FeatureDeviation &f : d.features) {
        if (f.featureId != featureId || f.stations.empty())
            continue;
        const auto &st = f.stations;
        if (st.size() == 1 || z <= st.front().z_mm)
            return st.front().radiusError_mm;
        for (std::size_t i = 1; i < st.size(); ++i) {
            if (z <= st[i].z_mm) {
                const double span = st[i].z_mm - st[i - 1].z_mm;
                const double t = span > 0.0 ? (z - st[i - 1].z_mm) / span : 0.0;
                return st[i - 1].radiusError_mm + t * (st[i].radiusError_mm - st[i - 1].radiusError_mm);
            }
        }
        return st.back().radiusError_mm;
    }
    return std::nullopt;
}

// The spindle speed where the tool is at z (under constant cutting speed it changes along a cone
// or a face): the nearest station's.
double spindleSpeedAt(const DeviationResult &d, const QString &featureId, double z)
{
    for (const FeatureDeviation &f : d.features) {
        if (f.featureId != featureId || f.stations.empty())
            continue;
        const auto nearest =
            std::min_element(f.stations.begin(), f.stations.end(), [z](const Station &a, const Station &b) {
                return std::abs(a.z_mm - z) < std::abs(b.z_mm - z);
            });
        return nearest->spindleSpeed_rpm;
    }
    return 0.0;
}

// The sample of a point on a feature, without its measured value: the programmed diameter, the
// physics' radius error and Li & Du's inputs. Empty where the program has no target or the model
// no station (a face, a feature not turned).
std::optional<ResidualSample> sampleAt(const Project &project, const DeviationResult &d, const ProgramTargets &targets,
                                       const QString &featureId, double z, double timeSinceStart_min, double ambient_C,
                                       const CuttingForces *measuredForces = nullptr)
{
    const bool inner = std::any_of(project.part.inner.segments.begin(), project.part.inner.segments.end(),
                                   [&featureId](const Segment &s) { return s.id == featureId; });
    const auto target = targetRadius_mm(inner ? targets.inner : targets.outer, featureId, z);
    const auto physics = physicsAt(d, featureId, z);
    if (!target || !physics)
        return std::nullopt;
    const TurningInputs &in = *d.inputs;
    ResidualSample s;
    s.featureId = featureId;
    s.inner = inner;
    s.z_mm = z;
    s.diameter_mm = 2.0 * *target;
    s.physics_mm = *physics;
    const auto inputsWith = [&](const CuttingForces &f) {
        Eigen::Matrix<double, 8, 1> x;
        x << spindleSpeedAt(d, featureId, z), in.pass.feed_mm_rev, timeSinceStart_min, ambient_C,
            f.tangential_N * *target * 1e-3, f.axial_N, f.radial_N, z;
        return x;
    };
    s.predictionInputs = inputsWith(in.forces);
    s.inputs = measuredForces ? inputsWith(*measuredForces) : s.predictionInputs;
    return s;
}

// The forces of a part's finishing cut from its drives' motor currents (Li & Du eq. 7–19), when
// it carries their readings and a calibrated estimator is given; else nothing, and the physics
// model's forces are the network's inputs.
std::optional<CuttingForces> forcesFromCurrents(const MeasuredPart &part, const Project &project,
                                                const TurningInputs &in, const DataLibrary &data,
                                                const CurrentForceModel *estimator, Diagnostics &warnings)
{
    if (!part.drive || !estimator)
        return std::nullopt;
    const QString field = QStringLiteral("parts[%1].drive").arg(part.id);
    Diagnostics problems;
    const auto tool = resolveLiDuToolGeometry(project, data, problems);
    CuttingForceEstimate e;
    if (tool) {
        const ToolAngles angles{tool->normalRake_rad, tool->backRake_rad,
                                0.5 * std::numbers::pi - tool->leadAngle_rad}; // γ_L = 90° − κ_r
        e = estimator->estimate(*part.drive, angles, in.pass.feed_mm_rev, in.pass.depthOfCut_mm, tool->noseRadius_mm);
        problems.insert(problems.end(), e.diagnostics.begin(), e.diagnostics.end());
    }
    for (const Diagnostic &d : problems)
        warnings.push_back(makeWarning(field, MeasuredResiduals::tr("part %1: %2").arg(part.id).arg(d.toString())));
    if (!e.forces)
        warnings.push_back(makeWarning(field, MeasuredResiduals::tr("part %1: its forces are the physics model's, "
                                                                    "not estimated from its motor currents")
                                                  .arg(part.id)));
    return e.forces;
}

// One set-up of a measured part's snapshot as the predictions see it (operationView): the part
// as held, z from the held end, and its physics.
struct SetUpPhysics {
    Project view;
    DeviationResult deviation;
    ProgramTargets targets;
    bool mirrored = false; // held at the drawing's right end: z' = L − z
};

// The set-up that cuts `featureId`, computed once per part.
const SetUpPhysics *setUpOf(const Project &drawn, const QString &featureId, const DataLibrary &data,
                            std::map<int, std::optional<SetUpPhysics>> &setUps)
{
    const int op = operationOf(drawn, featureId);
    auto it = setUps.find(op);
    if (it == setUps.end()) {
        SetUpPhysics s;
        s.view = operationView(drawn, op);
        s.deviation = computeDeviation(s.view, data, {});
        s.targets = programTargets(s.view);
        s.mirrored = s.view.clamping.heldEnd == PartEnd::Right;
        it = setUps.emplace(op, s.deviation.inputs ? std::optional<SetUpPhysics>(std::move(s)) : std::nullopt).first;
    }
    return it->second ? &*it->second : nullptr;
}

// The samples a prediction has at every station of a deviation result (its features in order,
// their stations in order): none where the model does not turn a point.
std::vector<std::vector<std::optional<ResidualSample>>>
stationSamples(const Project &project, const DeviationResult &deviation, const ProgramTargets &targets)
{
    std::vector<std::vector<std::optional<ResidualSample>>> out;
    if (!deviation.inputs)
        return out;
    for (const FeatureDeviation &f : deviation.features) {
        std::vector<std::optional<ResidualSample>> feature;
        feature.reserve(f.stations.size());
        for (const Station &st : f.stations)
            feature.push_back(sampleAt(project, deviation, targets, f.featureId, st.z_mm,
                                       deviation.inputs->timeSinceStart_min, deviation.inputs->ambientTemperature_C));
        out.push_back(std::move(feature));
    }
    return out;
}

// The spans of the conditions of `samples` (not empty) as the network saw them (ResidualSample::
// inputs: [0] spindle speed, [1] feed, [2] time since start, [3] ambient, [6] radial force, [7] z),
// and the programmed diameter.
LearnedDomain domainOf(const std::vector<ResidualSample> &samples)
{
    const auto span = [&samples](const std::function<double(const ResidualSample &)> &of) {
        LearnedDomain::Span s{of(samples.front()), of(samples.front())};
        for (const ResidualSample &r : samples) {
            s.min = std::min(s.min, of(r));
            s.max = std::max(s.max, of(r));
        }
        return s;
    };
    const auto input = [&span](Eigen::Index i) { return span([i](const ResidualSample &r) { return r.inputs[i]; }); };
    return {input(0), input(1), input(6),
            input(2), input(3), span([](const ResidualSample &r) { return r.diameter_mm; }),
            input(7)};
}

QString spanText(LearnedDomain::Span s, int decimals)
{
    return QStringLiteral("%1–%2").arg(s.min, 0, 'f', decimals).arg(s.max, 0, 'f', decimals);
}

// Adds the samples of one part; true when its forces came from its motor currents. Each point is
// compared with the set-up that cuts its feature, in that set-up's frame (z from the held end), as
// a prediction of that set-up has it.
bool addPartSamples(const MeasuredPart &part, const DataLibrary &data, const CurrentForceModel *estimator,
                    std::vector<ResidualSample> &out, Diagnostics &warnings)
{
    const ProjectParseResult read = parseProjectJson(part.projectJson);
    const QString field = QStringLiteral("parts[%1]").arg(part.id);
    if (!read.project) {
        warnings.push_back(makeWarning(field, MeasuredResiduals::tr("part %1 is left out: its project snapshot "
                                                                    "does not read")
                                                  .arg(part.id)));
        return false;
    }
    const Project &drawn = *read.project;
    std::map<int, std::optional<SetUpPhysics>> setUps;
    const SetUpPhysics *first = setUpOf(drawn, {}, data, setUps);
    if (first == nullptr) {
        warnings.push_back(makeWarning(field, MeasuredResiduals::tr("part %1 is left out: the physics model cannot "
                                                                    "compute its project")
                                                  .arg(part.id)));
        return false;
    }
    const TurningInputs &firstInputs = *first->deviation.inputs;
    const std::optional<CuttingForces> measured =
        forcesFromCurrents(part, first->view, firstInputs, data, estimator, warnings);
    int unused = 0;
    int withModelForces = 0; // points of later set-ups while the currents are the first's
    for (const MeasuredPoint &p : part.points) {
        const SetUpPhysics *setUp = setUpOf(drawn, p.featureId, data, setUps);
        if (setUp == nullptr) {
            ++unused;
            continue;
        }
        const double z = setUp->mirrored ? drawn.part.length_mm() - p.z_mm : p.z_mm;
        const TurningInputs &in = *setUp->deviation.inputs;
        // The drives' readings are of the first set-up's finishing cut (docs/learning.md): the
        // forces of another set-up's cut are the force model's.
        const bool currentsOfThisCut = measured && setUp == first;
        auto s = sampleAt(setUp->view, setUp->deviation, setUp->targets, p.featureId, z,
                          part.timeSinceStart_min.value_or(in.timeSinceStart_min),
                          part.ambient_C.value_or(in.ambientTemperature_C), currentsOfThisCut ? &*measured : nullptr);
        if (!s) {
            ++unused; // a face or a feature the model does not turn: nothing to compare
            continue;
        }
        if (measured && !currentsOfThisCut)
            ++withModelForces;
        s->partId = part.id;
        // As the physics model's radius error: machined radius − programmed radius. A radial
        // deviation is recorded as material left, which on a bore is a radius short.
        const double target = 0.5 * s->diameter_mm;
        switch (p.quantity) {
        case MeasuredQuantity::Diameter:
            s->measured_mm = 0.5 * p.value_mm - target;
            break;
        case MeasuredQuantity::CmmPoint: // its radius √(x² + y²)
            s->measured_mm = p.value_mm - target;
            break;
        case MeasuredQuantity::RadialDeviation:
            s->measured_mm = s->inner ? -p.value_mm : p.value_mm;
            break;
        }
        out.push_back(*s);
    }
    if (unused > 0)
        warnings.push_back(makeWarning(
            field, MeasuredResiduals::tr("part %1: %2 of its %3 points are not compared with the physics (on a face or "
                                         "on a feature its set-up's passes do not turn)")
                       .arg(part.id)
                       .arg(unused)
                       .arg(part.points.size())));
    if (withModelForces > 0)
        warnings.push_back(makeWarning(
            QStringLiteral("parts[%1].drive").arg(part.id),
            MeasuredResiduals::tr("part %1: its motor currents are of the first set-up's finishing cut; %2 points "
                                  "cut in a later set-up are compared at the force model's forces")
                .arg(part.id)
                .arg(withModelForces)));
    return measured.has_value();
}

std::optional<GeometricError> fitGeometric(const std::vector<ResidualSample> &samples,
                                           const std::vector<double> &explained)
{
    // Least squares on [φ z 1]; a column with no spread (one diameter, one z) is left out.
    const auto n = static_cast<Eigen::Index>(samples.size());
    if (n < 3)
        return std::nullopt;
    Eigen::MatrixXd a(n, 3);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const ResidualSample &s = samples[static_cast<std::size_t>(i)];
        a.row(i) << s.diameter_mm, s.z_mm, 1.0;
        y[i] = s.residual_mm() - (explained.empty() ? 0.0 : explained[static_cast<std::size_t>(i)]);
    }
    std::vector<Eigen::Index> used;
    for (Eigen::Index c = 0; c < 2; ++c) {
        if (a.col(c).maxCoeff() - a.col(c).minCoeff() > 1e-9)
            used.push_back(c);
    }
    used.push_back(2);
    Eigen::MatrixXd reduced(n, static_cast<Eigen::Index>(used.size()));
    for (std::size_t k = 0; k < used.size(); ++k)
        reduced.col(static_cast<Eigen::Index>(k)) = a.col(used[k]);
    const Eigen::VectorXd w = reduced.colPivHouseholderQr().solve(y);
    Eigen::Vector3d full = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < used.size(); ++k)
        full[used[k]] = w[static_cast<Eigen::Index>(k)];
    return GeometricError{full[0], full[1], full[2]};
}

} // namespace

std::vector<ResidualSample> residualSamples(const std::vector<MeasuredPart> &parts, const DataLibrary &data,
                                            Diagnostics &warnings, const CurrentForceModel *forcesFromCurrents,
                                            int *partsWithCurrentForces)
{
    std::vector<ResidualSample> out;
    int fromCurrents = 0;
    for (const MeasuredPart &part : parts)
        fromCurrents += addPartSamples(part, data, forcesFromCurrents, out, warnings) ? 1 : 0;
    if (partsWithCurrentForces)
        *partsWithCurrentForces = fromCurrents;
    return out;
}

QJsonObject physicsBasis(const Project &project)
{
    QJsonObject basis = projectJsonObject(project).value(QStringLiteral("characterisation")).toObject();
    basis.remove(QStringLiteral("source"));
    return basis;
}

double LearnedResidual::predict_mm(const ResidualSample &s) const
{
    const double rest = network ? network->predict(s.predictionInputs) : 0.0;
    return geometric.at(s.diameter_mm, s.z_mm) + rest;
}

std::optional<LearnedResidual> learnResidual(const std::vector<ResidualSample> &samples,
                                             const RbfTrainingOptions &options, QString *error)
{
    auto geometric = fitGeometric(samples, {});
    if (!geometric) {
        if (error)
            *error = MeasuredResiduals::tr("%1 measured points; learning needs at least 3").arg(samples.size());
        return std::nullopt;
    }
    const auto n = static_cast<Eigen::Index>(samples.size());
    Eigen::MatrixXd x(n, 8);
    for (Eigen::Index i = 0; i < n; ++i)
        x.row(i) = samples[static_cast<std::size_t>(i)].inputs.transpose();
    // Backfitting (Hastie & Tibshirani, Generalized Additive Models, 1990, §4.3): the plane and
    // the network each fitted to what the other leaves, so that a warm-up drift that differs from
    // part to part does not bias the geometric error, nor the geometric error the network.
    LearnedResidual learned;
    std::vector<double> networkPart(samples.size(), 0.0);
    for (int pass = 0; pass < kBackfittingPasses; ++pass) {
        Eigen::VectorXd y(n);
        for (Eigen::Index i = 0; i < n; ++i) {
            const ResidualSample &s = samples[static_cast<std::size_t>(i)];
            y[i] = s.residual_mm() - geometric->at(s.diameter_mm, s.z_mm);
        }
        learned.network = trainHybridRbf(x, y, options, error);
        if (!learned.network)
            return std::nullopt;
        for (Eigen::Index i = 0; i < n; ++i)
            networkPart[static_cast<std::size_t>(i)] = learned.network->predict(x.row(i).transpose());
        geometric = fitGeometric(samples, networkPart);
    }
    learned.geometric = *geometric;
    learned.learnedFrom = domainOf(samples);
    // The network's last fit was to the plane before; once more to the final plane.
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const ResidualSample &s = samples[static_cast<std::size_t>(i)];
        y[i] = s.residual_mm() - learned.geometric.at(s.diameter_mm, s.z_mm);
    }
    learned.network = trainHybridRbf(x, y, options, error);
    if (!learned.network)
        return std::nullopt;
    return learned;
}

std::optional<CrossValidation> leaveOnePartOut(const std::vector<ResidualSample> &samples,
                                               const RbfTrainingOptions &options, QString *error,
                                               const LearningControl &control)
{
    std::map<qint64, std::vector<std::size_t>> byPart;
    for (std::size_t i = 0; i < samples.size(); ++i)
        byPart[samples[i].partId].push_back(i);
    if (byPart.size() < 2) {
        if (error)
            *error = MeasuredResiduals::tr("%1 measured part(s); leaving one out needs at least 2").arg(byPart.size());
        return std::nullopt;
    }
    CrossValidation cv;
    double physics = 0.0, learned = 0.0;
    const int folds = static_cast<int>(byPart.size());
    for (const auto &[part, rows] : byPart) {
        if (control.cancelled && control.cancelled()) {
            if (error)
                *error = MeasuredResiduals::tr("cancelled");
            return std::nullopt;
        }
        if (control.progress)
            control.progress(cv.parts, folds);
        std::vector<ResidualSample> training;
        for (const ResidualSample &s : samples) {
            if (s.partId != part)
                training.push_back(s);
        }
        const auto model = learnResidual(training, options, error);
        if (!model) {
            // The count is of the other parts' points, not of all: say which fold it is.
            if (error && !error->isEmpty())
                *error = MeasuredResiduals::tr("with part %1 left out: %2").arg(part).arg(*error);
            return std::nullopt;
        }
        for (const std::size_t i : rows) {
            const ResidualSample &s = samples[i];
            physics += s.residual_mm() * s.residual_mm();
            const double e = s.residual_mm() - model->predict_mm(s);
            learned += e * e;
        }
        ++cv.parts;
        cv.points += static_cast<int>(rows.size());
    }
    if (control.progress)
        control.progress(folds, folds);
    cv.physicsRms_mm = std::sqrt(physics / cv.points);
    cv.learnedRms_mm = std::sqrt(learned / cv.points);
    return cv;
}

std::vector<std::vector<double>> learnedAtStations(const Project &project, const DeviationResult &deviation,
                                                   const LearnedResidual &learned)
{
    return learnedAtStations(project, deviation, learned, programTargets(project));
}

std::vector<std::vector<double>> learnedAtStations(const Project &project, const DeviationResult &deviation,
                                                   const LearnedResidual &learned, const ProgramTargets &targets)
{
    std::vector<std::vector<double>> out;
    for (const std::vector<std::optional<ResidualSample>> &feature : stationSamples(project, deviation, targets)) {
        std::vector<double> learnedAt;
        learnedAt.reserve(feature.size());
        for (const std::optional<ResidualSample> &s : feature)
            learnedAt.push_back(s ? learned.predict_mm(*s) : 0.0);
        out.push_back(std::move(learnedAt));
    }
    return out;
}

QString learnedDomainText(const LearnedDomain &domain)
{
    return MeasuredResiduals::tr("spindle speed %1 rpm, feed %2 mm/rev, passive force %3 N, %4 min since start, "
                                 "ambient %5 °C, diameter %6 mm, z %7 mm")
        .arg(spanText(domain.spindleSpeed_rpm, 0), spanText(domain.feed_mm_rev, 3), spanText(domain.passiveForce_N, 0),
             spanText(domain.timeSinceStart_min, 0), spanText(domain.ambient_C, 1), spanText(domain.diameter_mm, 1),
             spanText(domain.z_mm, 1));
}

// outsideLearnedDomain with the program's targets computed by the caller.
static QString outsideLearnedDomain(const Project &project, const DeviationResult &deviation,
                                    const LearnedResidual &learned, const ProgramTargets &targets)
{
    if (!learned.learnedFrom)
        return {};
    // The verdicts' features: an untoleranced chamfer no part was measured on is not a reason.
    QSet<QString> toleranced;
    for (const Tolerance &t : project.tolerances)
        toleranced.insert(t.featureId);
    std::vector<ResidualSample> planned;
    for (const auto &feature : stationSamples(project, deviation, targets))
        for (const std::optional<ResidualSample> &s : feature)
            if (s && toleranced.contains(s->featureId))
                planned.push_back(*s);
    if (planned.empty())
        return {};
    const LearnedDomain plan = domainOf(planned);
    const LearnedDomain &measured = *learned.learnedFrom;
    QStringList outside;
    const auto check = [&outside](const QString &what, LearnedDomain::Span p, LearnedDomain::Span m, int decimals) {
        // A tenth of the span, or 1 % of the value where the parts have (almost) none: the Gaussians
        // reach that far, and the mid-zone target of another tolerance is not another condition.
        const double margin = std::max(0.1 * (m.max - m.min), 0.01 * std::max(std::abs(m.min), std::abs(m.max)));
        if (p.min >= m.min - margin && p.max <= m.max + margin)
            return;
        outside << MeasuredResiduals::tr("%1 %2 (measured parts %3)")
                       .arg(what, spanText(p, decimals), spanText(m, decimals));
    };
    // The cutting conditions only: the diameters and z of the points are where the parts were
    // measured (a micrometer reading in the middle of each journal), which the plane in them spans.
    check(MeasuredResiduals::tr("spindle speed [rpm]"), plan.spindleSpeed_rpm, measured.spindleSpeed_rpm, 0);
    check(MeasuredResiduals::tr("feed [mm/rev]"), plan.feed_mm_rev, measured.feed_mm_rev, 3);
    check(MeasuredResiduals::tr("passive force [N]"), plan.passiveForce_N, measured.passiveForce_N, 0);
    check(MeasuredResiduals::tr("time since start [min]"), plan.timeSinceStart_min, measured.timeSinceStart_min, 0);
    check(MeasuredResiduals::tr("ambient temperature [°C]"), plan.ambient_C, measured.ambient_C, 1);
    if (outside.isEmpty())
        return {};
    return MeasuredResiduals::tr("This plan is cut at other conditions than the parts the learned model was "
                                 "measured on: %1. There what was learned is extrapolated (a condition the parts "
                                 "did not vary is taken to have no effect, and the network's correction fades "
                                 "away from the conditions it learned at); measure parts cut at these conditions")
        .arg(outside.join(QStringLiteral("; ")));
}

QString outsideLearnedDomain(const Project &project, const DeviationResult &deviation, const LearnedResidual &learned)
{
    return outsideLearnedDomain(project, deviation, learned, programTargets(project));
}

void addLearnedResidual(const Project &project, DeviationResult &deviation, const LearnedResidual &learned,
                        const ProgramTargets &targets)
{
    const std::vector<std::vector<double>> add = learnedAtStations(project, deviation, learned, targets);
    for (std::size_t f = 0; f < deviation.features.size() && f < add.size(); ++f) {
        std::vector<Station> &stations = deviation.features[f].stations;
        for (std::size_t i = 0; i < stations.size() && i < add[f].size(); ++i)
            stations[i].radiusError_mm += add[f][i];
    }
}

DeviationResult withLearnedResidual(const Project &project, DeviationResult deviation, const LearnedResidual &learned,
                                    const QString &provenance)
{
    const ProgramTargets targets = programTargets(project);
    const QString outside = outsideLearnedDomain(project, deviation, learned, targets);
    addLearnedResidual(project, deviation, learned, targets);
    if (deviation.inputs)
        deviation.inputs->notes << MeasuredResiduals::tr(
                                       "The predicted radius errors include what was learned from measured parts (%1): "
                                       "the machine's measured behaviour replaces its stiffness range.")
                                       .arg(provenance);
    if (!outside.isEmpty())
        deviation.diagnostics.push_back(makeWarning(QStringLiteral("learned"), outside + QLatin1Char('.')));
    return deviation;
}

} // namespace tolturn
