// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/end_milling.h"

#include <cmath>
#include <numbers>

namespace tolturn {

MillingForces toothForces(const MillingForceCoefficients &k, const EndMillingCut &cut, double phi)
{
    if (phi < cut.entryAngle_rad || phi > cut.exitAngle_rad)
        return {};
    const double a = cut.axialDepth_mm;
    const double h = cut.feedPerTooth_mm * std::sin(phi); // Altintas eq. 2.51
    const double ft = k.tangentialCutting_N_mm2 * a * h + k.tangentialEdge_N_mm * a;
    const double fr = k.radialCutting_N_mm2 * a * h + k.radialEdge_N_mm * a;
    const double fa = k.axialCutting_N_mm2 * a * h + k.axialEdge_N_mm * a;
    return {-ft * std::cos(phi) - fr * std::sin(phi), ft * std::sin(phi) - fr * std::cos(phi), fa};
}

MillingForces meanMillingForces(const MillingForceCoefficients &k, const EndMillingCut &cut)
{
    const double n = cut.flutes;
    const double a = cut.axialDepth_mm;
    const double c = cut.feedPerTooth_mm;
    const double pi = std::numbers::pi;
    // The antiderivatives of Altintas eq. 2.55–2.57, evaluated at φ.
    const auto x = [&](double phi) {
        return n * a * c / (8.0 * pi) *
                   (k.tangentialCutting_N_mm2 * std::cos(2.0 * phi) -
                    k.radialCutting_N_mm2 * (2.0 * phi - std::sin(2.0 * phi))) +
               n * a / (2.0 * pi) * (-k.tangentialEdge_N_mm * std::sin(phi) + k.radialEdge_N_mm * std::cos(phi));
    };
    const auto y = [&](double phi) {
        return n * a * c / (8.0 * pi) *
                   (k.tangentialCutting_N_mm2 * (2.0 * phi - std::sin(2.0 * phi)) +
                    k.radialCutting_N_mm2 * std::cos(2.0 * phi)) -
               n * a / (2.0 * pi) * (k.tangentialEdge_N_mm * std::cos(phi) + k.radialEdge_N_mm * std::sin(phi));
    };
    const auto z = [&](double phi) {
        return n * a / (2.0 * pi) * (-k.axialCutting_N_mm2 * c * std::cos(phi) + k.axialEdge_N_mm * phi);
    };
    const double st = cut.entryAngle_rad;
    const double ex = cut.exitAngle_rad;
    return {x(ex) - x(st), y(ex) - y(st), z(ex) - z(st)};
}

EndMillingCut downMilling(int flutes, double diameter_mm, double radialDepth_mm, double axialDepth_mm,
                          double feedPerTooth_mm)
{
    EndMillingCut cut;
    cut.flutes = flutes;
    cut.axialDepth_mm = axialDepth_mm;
    cut.feedPerTooth_mm = feedPerTooth_mm;
    cut.entryAngle_rad = std::numbers::pi - std::acos(1.0 - 2.0 * radialDepth_mm / diameter_mm);
    cut.exitAngle_rad = std::numbers::pi;
    return cut;
}

} // namespace tolturn
