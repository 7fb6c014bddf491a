// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/milling/ball_end_deflection.h"

#include "core/milling/seed_ball_end_cases.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace tolturn {

namespace {

struct BallEndMilling {
    Q_DECLARE_TR_FUNCTIONS(BallEndMilling)
};

double secondMomentOfArea_mm4(double diameter_mm)
{
    return std::numbers::pi * std::pow(diameter_mm, 4) / 64.0;
}

} // namespace

double lateralCompliance_mm_N(const BallEndToolStructure &tool, double forceFromHolder_mm, double pointFromHolder_mm)
{
    const double vm = forceFromHolder_mm;
    const double vk = pointFromHolder_mm;
    const double ei = tool.youngsModulus_N_mm2 * secondMomentOfArea_mm4(tool.equivalentDiameter_mm);
    const double beam = vm >= vk ? vk * vk * (3.0 * vm - vk) / (6.0 * ei) : vm * vm * (3.0 * vk - vm) / (6.0 * ei);
    return beam + 1.0 / tool.holderStiffness_N_mm + vm * vk / tool.holderRotational_N_mm_rad;
}

double axialCompliance_mm_N(const BallEndToolStructure &tool)
{
    const double area = std::numbers::pi * tool.equivalentDiameter_mm * tool.equivalentDiameter_mm / 4.0;
    return tool.overhang_mm / (tool.youngsModulus_N_mm2 * area);
}

double surfaceGenerationHeight_mm(const BallEndMill &mill, const BallEndCut &cut)
{
    return 0.5 * mill.diameter_mm * (1.0 - std::cos(toolAxisInclination_rad(cut.lead_rad, cut.tilt_rad)));
}

std::vector<std::string> validateToolStructure(const BallEndToolStructure &tool, const BallEndMill &mill)
{
    std::vector<std::string> problems;
    const auto add = [&](const QString &message) { problems.push_back(message.toStdString()); };
    if (!(tool.overhang_mm >= 0.5 * mill.diameter_mm && tool.overhang_mm <= 1000.0))
        add(BallEndMilling::tr("overhang: %1 mm is not from the ball's radius, %2 mm, to 1000 mm")
                .arg(tool.overhang_mm)
                .arg(0.5 * mill.diameter_mm));
    if (!(tool.equivalentDiameter_mm > 0.0 && tool.equivalentDiameter_mm <= mill.diameter_mm))
        add(BallEndMilling::tr("equivalent diameter: %1 mm is not above 0 and at most the tool's %2 mm")
                .arg(tool.equivalentDiameter_mm)
                .arg(mill.diameter_mm));
    if (!(tool.youngsModulus_N_mm2 > 0.0))
        add(BallEndMilling::tr("Young's modulus: %1 N/mm² is not positive").arg(tool.youngsModulus_N_mm2));
    if (!(tool.holderStiffness_N_mm > 0.0))
        add(BallEndMilling::tr("holder stiffness k: %1 N/mm is not positive").arg(tool.holderStiffness_N_mm));
    if (!(tool.holderRotational_N_mm_rad > 0.0))
        add(BallEndMilling::tr("holder rotational stiffness k_θ: %1 N·mm/rad is not positive")
                .arg(tool.holderRotational_N_mm_rad));
    return problems;
}

BallEndDeflection ballEndDeflection(const BallEndMill &mill, const BallEndToolStructure &tool,
                                    const MillingForceCoefficients &coefficients, const BallEndCut &cut,
                                    const BallEndResolution &resolution)
{
    if (const std::vector<std::string> problems = validateToolStructure(tool, mill); !problems.empty())
        throw std::invalid_argument(problems.front());
    if (const std::vector<std::string> problems = validateBallEndCut(mill, cut, resolution); !problems.empty())
        throw std::invalid_argument(problems.front());
    // v_k: the holder to the generating point; v_m: the holder to each element (001 fig. 6).
    const double pointFromHolder = tool.overhang_mm - surfaceGenerationHeight_mm(mill, cut);
    BallEndSliceCompliance compliance;
    compliance.axial_mm_N = axialCompliance_mm_N(tool);
    compliance.lateral_mm_N.reserve(static_cast<std::size_t>(resolution.axialSlices));
    for (const double z : sliceHeights_mm(mill, cut, resolution))
        compliance.lateral_mm_N.push_back(lateralCompliance_mm_N(tool, tool.overhang_mm - z, pointFromHolder));

    BallEndDeflection result;
    result.forces = ballEndForces(mill, coefficients, cut, resolution, &compliance);
    const Eigen::Matrix3d toWorkpiece = leadTiltTransform(cut.lead_rad, cut.tilt_rad);
    result.deflection.reserve(result.forces.size());
    result.leastSurfaceNormal_mm = std::numeric_limits<double>::infinity();
    result.greatestSurfaceNormal_mm = -std::numeric_limits<double>::infinity();
    for (const BallEndForceSample &f : result.forces) {
        // δ_x, δ_y, δ_z into F, C, N through T, and δ_N its N component (001 §4).
        const BallEndDeflectionSample d{f.rotation_rad, f.deflection_mm, toWorkpiece * f.deflection_mm};
        result.leastSurfaceNormal_mm = std::min(result.leastSurfaceNormal_mm, d.surfaceNormal_mm());
        result.greatestSurfaceNormal_mm = std::max(result.greatestSurfaceNormal_mm, d.surfaceNormal_mm());
        result.deflection.push_back(d);
    }
    return result;
}

QStringList ballEndValidityWarnings(const BallEndMill &mill, const BallEndToolStructure &tool, const BallEndCut &cut,
                                    const BallEndDeflection &deflection)
{
    QStringList out;
    if (engagedBand(mill, cut).low_mm <= 0.0)
        out << BallEndMilling::tr("the tip of the ball, where the cutting speed is zero, is in the cut (lead %1°, tilt "
                                  "%2°): the force model takes no account of the rubbing there")
                   .arg(cut.lead_rad * 180.0 / std::numbers::pi, 0, 'f', 1)
                   .arg(cut.tilt_rad * 180.0 / std::numbers::pi, 0, 'f', 1);
    if (cut.lead_rad < 0.0)
        out << BallEndMilling::tr("the lead is negative (%1°): the feed has a part along the tool axis and the cut "
                                  "drills, where 001 §5 finds its force model below the measured forces")
                   .arg(cut.lead_rad * 180.0 / std::numbers::pi, 0, 'f', 1);
    double peak = 0.0;
    for (const BallEndForceSample &f : deflection.forces)
        peak = std::max(peak, std::hypot(f.toolFrame_N.x(), f.toolFrame_N.y()));
    constexpr double kSeedHolderCalibration_N = 1000.0; // 001 §4
    if (tool.holderStiffness_N_mm == kSeedHolderStiffness_N_mm &&
        tool.holderRotational_N_mm_rad == kSeedHolderRotational_N_mm_rad && peak > kSeedHolderCalibration_N)
        out << BallEndMilling::tr("the lateral force peaks at %1 N, beyond the 1000 N for which 001 calibrated the "
                                  "holder springs it gives (001 §4): the deflection there is an extrapolation; give "
                                  "your holder's springs")
                   .arg(peak, 0, 'f', 0);
    return out;
}

} // namespace tolturn
