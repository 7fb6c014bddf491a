// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/milling/ball_end_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tolturn {

namespace {

// acos of a ratio that rounding may carry just outside [−1, 1].
double clampedAcos(double ratio)
{
    return std::acos(std::clamp(ratio, -1.0, 1.0));
}

} // namespace

double localRadius_mm(double ballRadius_mm, double z_mm)
{
    if (z_mm <= 0.0)
        return 0.0;
    if (z_mm >= ballRadius_mm)
        return ballRadius_mm;
    const double d = ballRadius_mm - z_mm;
    return std::sqrt(ballRadius_mm * ballRadius_mm - d * d);
}

double uncutEngagementHeight_mm(double ballRadius_mm, double radialDepth_mm, double axialDepth_mm)
{
    const double d = std::min(std::abs(radialDepth_mm - localRadius_mm(ballRadius_mm, axialDepth_mm)), ballRadius_mm);
    return ballRadius_mm - std::sqrt(ballRadius_mm * ballRadius_mm - d * d);
}

double scallopHeight_mm(double ballRadius_mm, double stepOver_mm)
{
    const double half = std::min(0.5 * stepOver_mm, ballRadius_mm);
    return ballRadius_mm - std::sqrt(ballRadius_mm * ballRadius_mm - half * half);
}

Engagement uncutEngagement(double ballRadius_mm, double radialDepth_mm, double axialDepth_mm, double z_mm,
                           MillingDirection direction)
{
    constexpr double pi = std::numbers::pi;
    const double ra = localRadius_mm(ballRadius_mm, axialDepth_mm);
    if (z_mm >= uncutEngagementHeight_mm(ballRadius_mm, radialDepth_mm, axialDepth_mm)) {
        const double r = localRadius_mm(ballRadius_mm, z_mm);
        const double edge = r > 0.0 ? clampedAcos((ra - radialDepth_mm) / r) : 0.0;
        return direction == MillingDirection::Down ? Engagement{pi - edge, pi} : Engagement{0.0, edge};
    }
    // Below hc: the whole half of the element cuts where the cut is at least as wide as R(a),
    // none of it where it is narrower (001 table 1).
    if (radialDepth_mm >= ra)
        return {0.0, pi};
    return direction == MillingDirection::Down ? Engagement{pi, pi} : Engagement{0.0, 0.0};
}

Engagement previouslyCutEngagement(double ballRadius_mm, double stepOver_mm, double z_mm, MillingDirection direction)
{
    constexpr double pi = std::numbers::pi;
    if (z_mm < scallopHeight_mm(ballRadius_mm, stepOver_mm))
        return {0.0, pi};
    const double r = localRadius_mm(ballRadius_mm, z_mm);
    const double edge = r > 0.0 ? clampedAcos(1.0 - stepOver_mm / r) : 0.0;
    return direction == MillingDirection::Down ? Engagement{pi - edge, pi} : Engagement{0.0, edge};
}

Eigen::Matrix3d leadTiltTransform(double lead_rad, double tilt_rad)
{
    const double cl = std::cos(lead_rad);
    const double sl = std::sin(lead_rad);
    const double ct = std::cos(tilt_rad);
    const double st = std::sin(tilt_rad);
    Eigen::Matrix3d t;
    t << cl, 0.0, sl,          //
        sl * st, ct, -st * cl, //
        -ct * sl, st, ct * cl;
    return t;
}

double axialImmersionAngle_rad(double ballRadius_mm, double z_mm)
{
    return std::asin(std::clamp(localRadius_mm(ballRadius_mm, z_mm) / ballRadius_mm, 0.0, 1.0));
}

} // namespace tolturn
