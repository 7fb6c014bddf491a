// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/project_control.h"

#include "core/adaptive/pass_depth.h"
#include "core/deviation/deviation_model.h"
#include "core/mechanics/section.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

struct AdaptiveControl {
    Q_DECLARE_TR_FUNCTIONS(AdaptiveControl)
};

constexpr double kInfluenceStep_mm = 1.0; // the influence coefficients change slowly along z

// Fr (c_r + c_tp) + Fa c_a at z (deviation_model.cpp, sweepFormErrors), the coefficients
// interpolated between stations 1 mm apart on the finished section.
struct DeviationAlongZ {
    std::vector<double> z;
    std::vector<double> perRadial;
    std::vector<double> perAxial;

    double operator()(double at, const CuttingForces &f) const
    {
        const auto it = std::lower_bound(z.begin(), z.end(), at);
        const auto i = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(it - z.begin(), 1, std::ssize(z) - 1));
        const double t = std::clamp((at - z[i - 1]) / (z[i] - z[i - 1]), 0.0, 1.0);
        const auto lerp = [&](const std::vector<double> &v) { return v[i - 1] + t * (v[i] - v[i - 1]); };
        return f.radial_N * lerp(perRadial) + f.axial_N * lerp(perAxial);
    }
};

DeviationAlongZ deviationAlongZ(const Project &project, const TurningInputs &in, double left, double right)
{
    DeviationAlongZ d;
    const auto n = static_cast<int>(std::ceil((right - left) / kInfluenceStep_mm));
    std::vector<double> radius;
    const SectionAlongZ section(project.part);
    for (int i = 0; i <= std::max(n, 1); ++i) {
        const double z = std::min(right, left + i * kInfluenceStep_mm);
        d.z.push_back(z);
        radius.push_back(section.at(std::clamp(z, left + 1e-6, right - 1e-6)).outerRadius_mm);
    }
    for (const StationInfluence &s : influenceAt(project.part, in, d.z, radius)) {
        d.perRadial.push_back(s.radialPerRadial_mm_per_N + in.toolpostCompliance_mm_per_N);
        d.perAxial.push_back(s.radialPerAxial_mm_per_N);
    }
    return d;
}

// The largest feed a pass may run at: the top of the plan's feed range (the insert maker's), and
// for the finishing pass the roughness the drawing asks for, by the kinematic roughness
// Ra = f² / (32 r_e), Rz = f² / (8 r_e) (cutting_quantities.h) solved for f. `reasons` gets the
// roughness limits that bind below the range.
std::optional<double> feedCeiling(const Project &project, const CuttingPass &pass, double noseRadius_mm,
                                  QStringList &reasons)
{
    const PlanningSettings &s = project.planning;
    std::optional<double> ceiling;
    if (s.feed_mm_rev)
        ceiling = s.feed_mm_rev->max;
    const auto lower = [&](double f, const QString &why) {
        if (ceiling && f >= *ceiling)
            return;
        ceiling = f;
        reasons << why;
    };
    if (pass.kind == PassKind::Finishing && noseRadius_mm > 0.0) {
        if (s.maxRa_um)
            lower(std::sqrt(32.0 * noseRadius_mm * *s.maxRa_um / 1000.0),
                  AdaptiveControl::tr("Ra %1 µm").arg(QString::number(*s.maxRa_um)));
        if (s.maxRz_um)
            lower(std::sqrt(8.0 * noseRadius_mm * *s.maxRz_um / 1000.0),
                  AdaptiveControl::tr("Rz %1 µm").arg(QString::number(*s.maxRz_um)));
    }
    return ceiling;
}

QString feedRangeNote(const Project &project, const ForceControlSettings &control)
{
    const PlanningSettings &s = project.planning;
    if (!s.feed_mm_rev)
        return AdaptiveControl::tr("No feed limit known (the plan's settings give no feed range): the override's "
                                   "%1 % alone bounds the feed.")
            .arg(100.0 * control.maxOverride);
    return AdaptiveControl::tr("The feed is held at or below %1 mm/rev, the top of the plan's feed range (%2).")
        .arg(QString::number(s.feed_mm_rev->max, 'f', 3),
             s.rangesSource.isEmpty() ? AdaptiveControl::tr("no source given") : s.rangesSource);
}

QStringList notesFor(const ProjectControlOptions &options, const TurningInputs &in)
{
    QStringList notes;
    const ForceControlSettings &c = options.control;
    notes << AdaptiveControl::tr("Forces from the project's %1 model; feed drive 1/(%2 s² + %3 s + 1) (Čuš & Župerl "
                                 "eq. 1), control period %4 ms, feed override %5–%6 %.")
                 .arg(forceModelName(in.forceModel), QString::number(c.drive.a_s2), QString::number(c.drive.b_s),
                      QString::number(1000.0 * c.period_s), QString::number(100.0 * c.minOverride),
                      QString::number(100.0 * c.maxOverride));
    notes << (c.forceNoise > 0.0
                  ? AdaptiveControl::tr("Machine noise: %1 % of the force (standard deviation), seed %2.")
                        .arg(QString::number(100.0 * c.forceNoise))
                        .arg(c.noiseSeed)
                  : AdaptiveControl::tr("Machine noise: none (the force is measured exactly)."));
    notes += in.notes;
    return notes;
}

// The default set force is the force of the programmed feed at the pass's planned depth: where
// the passes before leave more, the pass cuts deeper and the loop lowers the feed to hold that
// force, which the planner should know (and the verdicts, computed at the planned depth, are
// optimistic there).
void warnWhereDeeperThanPlanned(const PassDepthProfile &pass, Diagnostics &out)
{
    if (pass.depth_mm.empty())
        return;
    const double deepest = *std::max_element(pass.depth_mm.begin(), pass.depth_mm.end());
    const double planned = pass.conditions.depthOfCut_mm;
    constexpr double kSlack = 1.1; // within 10 % the planned depth stands for the pass
    if (deepest <= kSlack * planned)
        return;
    out.push_back(makeWarning(QStringLiteral("passes[%1].depth_of_cut_mm").arg(pass.passIndex),
                              AdaptiveControl::tr("pass %1 cuts up to %2 mm deep where the plan gives %3 mm: the "
                                                  "passes before it leave more. The set force is the planned depth's, "
                                                  "so the loop lowers the feed there; plan the passes to the stock")
                                  .arg(pass.passIndex + 1)
                                  .arg(QString::number(deepest, 'f', 3), QString::number(planned, 'f', 3))));
}

} // namespace

ProjectControlSetup prepareProjectControl(const Project &project, const DataLibrary &data,
                                          const ProjectControlOptions &options)
{
    ProjectControlSetup setup;
    if (options.passIndex && (*options.passIndex < 0 || *options.passIndex >= std::ssize(project.passes))) {
        setup.diagnostics.push_back(
            makeError(QStringLiteral("passes"), AdaptiveControl::tr("pass %1 does not exist: the plan has %n pass(es)",
                                                                    nullptr, static_cast<int>(project.passes.size()))
                                                    .arg(*options.passIndex + 1)));
        return setup;
    }
    const std::optional<ForceFunction> forces = projectForceModel(project, data, setup.diagnostics);
    DeviationOptions deviation;
    deviation.stiffnessEnd = options.stiffnessEnd;
    deviation.passIndex = options.passIndex.value_or(-1);
    InputsResult inputs = resolveTurningInputs(project, data, deviation);
    setup.diagnostics.insert(setup.diagnostics.end(), inputs.diagnostics.begin(), inputs.diagnostics.end());
    if (!forces || !inputs.inputs || hasErrors(setup.diagnostics))
        return setup;
    const TurningInputs &in = *inputs.inputs;
    const double left = in.supportStart_mm + kToolClearance_mm;
    const double right = project.part.length_mm();
    if (right <= left) {
        setup.diagnostics.push_back(makeError(QStringLiteral("clamping.clamped_length_mm"),
                                              AdaptiveControl::tr("the tool cannot reach the part: it is held "
                                                                  "over its whole length")));
        return setup;
    }
    PassProcess process;
    process.forces = *forces;
    process.radialDeviation_mm = deviationAlongZ(project, in, left, right);
    process.maxSpindleSpeed_rpm = in.maxSpindleSpeed_rpm;
    process.noseRadius_mm = in.noseRadius_mm;
    QStringList ceilings;
    for (const PassDepthProfile &pass : passDepthProfiles(project, left, options.depthStep_mm)) {
        if (options.passIndex && pass.passIndex != *options.passIndex)
            continue;
        process.cuttingSpeed_m_min = pass.conditions.cuttingSpeed_m_min;
        warnWhereDeeperThanPlanned(pass, setup.diagnostics);
        QStringList reasons;
        process.maxFeed_mm_rev = feedCeiling(project, pass.conditions, in.noseRadius_mm, reasons);
        if (!reasons.isEmpty())
            ceilings << AdaptiveControl::tr("Pass %1: the feed is held at or below %2 mm/rev for %3 (f² / (32 r_e), "
                                            "f² / (8 r_e)).")
                            .arg(pass.passIndex + 1)
                            .arg(QString::number(*process.maxFeed_mm_rev, 'f', 3), reasons.join(QStringLiteral(", ")));
        setup.passes.push_back({pass, process});
    }
    setup.notes = notesFor(options, in) + QStringList{feedRangeNote(project, options.control)} + ceilings;
    return setup;
}

ProjectControlResult simulateProjectControl(const Project &project, const DataLibrary &data,
                                            const ProjectControlOptions &options)
{
    ProjectControlSetup setup = prepareProjectControl(project, data, options);
    ProjectControlResult result;
    result.diagnostics = std::move(setup.diagnostics);
    result.notes = std::move(setup.notes);
    if (hasErrors(result.diagnostics))
        return result;
    for (const PassSetup &p : setup.passes) {
        result.passes.push_back(simulatePassControl(p.pass, p.process, options.control));
        if (result.passes.back().adaptive.cutShort)
            result.diagnostics.push_back(
                makeWarning(QStringLiteral("passes"),
                            AdaptiveControl::tr(
                                "pass %1: the adaptive run was stopped after %2 h of cutting short of the end of the "
                                "pass: the set force asks for a feed the pass hardly advances at")
                                .arg(p.pass.passIndex + 1)
                                .arg(result.passes.back().adaptive.time_s / 3600.0, 0, 'f', 1)));
    }
    return result;
}

} // namespace tolturn
