// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cutting/cutting_quantities.h"

#include <cmath>
#include <numbers>

namespace tolturn {

double spindleSpeed_rpm(double cuttingSpeed_m_min, double diameter_mm)
{
    return 1000.0 * cuttingSpeed_m_min / (std::numbers::pi * diameter_mm);
}

double cuttingPower_kW(double cuttingForce_N, double cuttingSpeed_m_min)
{
    return cuttingForce_N * cuttingSpeed_m_min / 60.0 / 1000.0;
}

double spindleTorque_Nm(double cuttingForce_N, double diameter_mm)
{
    return cuttingForce_N * diameter_mm / 2.0 / 1000.0;
}

double theoreticalRa_um(double feed_mm_rev, double noseRadius_mm)
{
    return 1000.0 * feed_mm_rev * feed_mm_rev / (32.0 * noseRadius_mm);
}

double theoreticalRz_um(double feed_mm_rev, double noseRadius_mm)
{
    return 1000.0 * feed_mm_rev * feed_mm_rev / (8.0 * noseRadius_mm);
}

double feedForRa_mm_rev(double ra_um, double noseRadius_mm)
{
    return std::sqrt(32.0 * noseRadius_mm * ra_um / 1000.0);
}

double feedForRz_mm_rev(double rz_um, double noseRadius_mm)
{
    return std::sqrt(8.0 * noseRadius_mm * rz_um / 1000.0);
}

double noseRadiusForRa_mm(double ra_um, double feed_mm_rev)
{
    return 1000.0 * feed_mm_rev * feed_mm_rev / (32.0 * ra_um);
}

double noseRadiusForRz_mm(double rz_um, double feed_mm_rev)
{
    return 1000.0 * feed_mm_rev * feed_mm_rev / (8.0 * rz_um);
}

double speedForToolLife_m_min(double taylorC_m_min, double toolLife_min, double exponent)
{
    return taylorC_m_min / std::pow(toolLife_min, exponent);
}

double taylorConstant_m_min(double cuttingSpeed_m_min, double toolLife_min, double exponent)
{
    return cuttingSpeed_m_min * std::pow(toolLife_min, exponent);
}

} // namespace tolturn
