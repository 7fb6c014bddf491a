// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cutting/cutting_forces.h"

#include <Eigen/Dense>
#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tolturn {

namespace {

struct CuttingModels {
    Q_DECLARE_TR_FUNCTIONS(CuttingModels)
};

QString num(double v)
{
    return formatNumber(v);
}

double degrees(double rad)
{
    return rad * 180.0 / std::numbers::pi;
}

double kienzle(const KienzleLaw &law, double b_mm, double h_mm)
{
    return law.k11_MPa * b_mm * std::pow(h_mm, 1.0 - law.m);
}

void checkRange(Diagnostics &warnings, const QString &field, const QString &what, double value, double lo, double hi,
                const QString &model)
{
    // The bounds themselves count as inside: the paper's ranges are its test ranges, and a 95°
    // holder sits exactly on gamma_L = -5°.
    constexpr double kRounding = 1e-9; // 95° holders reach -5° only up to rounding
    if (value >= lo - kRounding && value <= hi + kRounding)
        return;
    warnings.push_back(
        makeWarning(field, CuttingModels::tr("%1 = %2 is outside the range %3 < %1 < %4 in which %5 is stated to hold")
                               .arg(what, num(value), num(lo), num(hi), model)));
}

struct LiDuFactors {
    double c1, c2, c3, c4, c5, c6; // Ft = A(c1 + Kf c2) Kn, Fa = A(c3 + Kf c4) Kn, Fr = A(c5 + Kf c6) Kn
};

LiDuFactors liDuFactors(const LiDuToolGeometry &tool, double effectiveLead_rad)
{
    const double a = tool.normalRake_rad;
    const double ab = tool.backRake_rad;
    const double g = effectiveLead_rad;
    return {std::cos(ab) * std::cos(a),
            std::cos(g) * std::sin(a) + std::sin(g) * std::sin(ab),
            -std::cos(ab) * std::sin(a),
            std::cos(g) * std::cos(a),
            -std::sin(ab),
            std::sin(g) * std::cos(ab)};
}

} // namespace

double equivalentEnteringAngle_rad(double enteringAngle_rad, double noseRadius_mm, double feed_mm_rev,
                                   double depthOfCut_mm, Diagnostics *warnings)
{
    if (!(noseRadius_mm > 0.0))
        return enteringAngle_rad;
    LiDuToolGeometry tool;
    tool.leadAngle_rad = 0.5 * std::numbers::pi - enteringAngle_rad;
    tool.noseRadius_mm = noseRadius_mm;
    return 0.5 * std::numbers::pi - liDuEffectiveLeadAngle_rad(tool, feed_mm_rev, depthOfCut_mm, warnings);
}

ForceResult kienzleForces(const KienzleConstants &constants, double feed_mm_rev, double depthOfCut_mm,
                          double enteringAngle_rad, double noseRadius_mm)
{
    const KienzleConstants &k = constants;
    ForceResult r;
    const double kappa =
        equivalentEnteringAngle_rad(enteringAngle_rad, noseRadius_mm, feed_mm_rev, depthOfCut_mm, &r.warnings);
    const double sinK = std::sin(kappa);
    const double h = feed_mm_rev * sinK;
    const double b = depthOfCut_mm / sinK;
    r.forces.tangential_N = kienzle(k.cutting, b, h);
    double feed = k.feed ? kienzle(*k.feed, b, h) : k.feedToCuttingRatio * r.forces.tangential_N;
    double passive = k.passive ? kienzle(*k.passive, b, h) : k.passiveToCuttingRatio * r.forces.tangential_N;
    if (kappa != enteringAngle_rad) {
        // The thrust turns towards the radial with the edge the chip leaves (kept between the feed
        // and the radial direction).
        const double thrust = std::hypot(feed, passive);
        const double direction =
            std::clamp(std::atan2(passive, feed) + (enteringAngle_rad - kappa), 0.0, 0.5 * std::numbers::pi);
        feed = thrust * std::cos(direction);
        passive = thrust * std::sin(direction);
    }
    r.forces.axial_N = feed;
    r.forces.radial_N = passive;
    if (k.validChipThicknessMax_mm > 0.0 && (h < k.validChipThicknessMin_mm || h > k.validChipThicknessMax_mm))
        r.warnings.push_back(makeWarning(
            QStringLiteral("feed_mm_rev"),
            CuttingModels::tr(
                "chip thickness h = f sin(kappa_r) = %1 mm is outside the range %2–%3 mm over which the Kienzle "
                "constants of this material were measured")
                .arg(num(h), num(k.validChipThicknessMin_mm), num(k.validChipThicknessMax_mm))));
    return r;
}

double liDuUncutChipArea_mm2(double feed_mm_rev, double depthOfCut_mm, double noseRadius_mm)
{
    const double f = feed_mm_rev;
    const double rn = noseRadius_mm;
    if (rn < 0.5 * f)
        return f * depthOfCut_mm;                                                  // eq. 16b
    return f * depthOfCut_mm - f * (rn - std::sqrt(rn * rn - 0.25 * f * f)) / 2.0; // eq. 16a
}

double liDuEffectiveLeadAngle_rad(const LiDuToolGeometry &tool, double feed_mm_rev, double depthOfCut_mm,
                                  Diagnostics *warnings)
{
    if (warnings != nullptr) {
        const QString model = CuttingModels::tr("eq. 20 of Li & Du (2002)");
        checkRange(*warnings, QStringLiteral("tool.lead_angle"), CuttingModels::tr("lead angle [°]"),
                   degrees(tool.leadAngle_rad), -5.0, 45.0, model);
        checkRange(*warnings, QStringLiteral("depth_of_cut_mm"), CuttingModels::tr("depth of cut [mm]"), depthOfCut_mm,
                   0.5, 5.0, model);
        checkRange(*warnings, QStringLiteral("feed_mm_rev"), CuttingModels::tr("feed [mm/rev]"), feed_mm_rev, 0.1, 1.0,
                   model);
        checkRange(*warnings, QStringLiteral("tool.nose_radius_mm"), CuttingModels::tr("nose radius [mm]"),
                   tool.noseRadius_mm, 0.4, 4.4, model);
        if (!(tool.noseRadius_mm > feed_mm_rev))
            warnings->push_back(
                makeWarning(QStringLiteral("feed_mm_rev"),
                            CuttingModels::tr("eq. 20 of Li & Du (2002) needs a nose radius larger than the feed, "
                                              "but r_n = %1 mm and f = %2 mm/rev")
                                .arg(num(tool.noseRadius_mm), num(feed_mm_rev))));
    }
    // tan(gamma_Le) = 0.5053 tan(gamma_L) + 1.0473 f / r_n + 0.4654 r_n / d   (eq. 20)
    const double t = 0.5053 * std::tan(tool.leadAngle_rad) + 1.0473 * feed_mm_rev / tool.noseRadius_mm +
                     0.4654 * tool.noseRadius_mm / depthOfCut_mm;
    return std::atan(t);
}

ForceResult liDuForces(const LiDuCoefficients &c, const LiDuToolGeometry &tool, double feed_mm_rev,
                       double depthOfCut_mm)
{
    ForceResult r;
    const double gle = liDuEffectiveLeadAngle_rad(tool, feed_mm_rev, depthOfCut_mm, &r.warnings);
    const double area = liDuUncutChipArea_mm2(feed_mm_rev, depthOfCut_mm, tool.noseRadius_mm);
    const LiDuFactors k = liDuFactors(tool, gle);
    const double kn = c.normalPressure_MPa;
    const double kf = c.frictionRatio;
    r.forces.tangential_N = kn * area * (k.c1 + kf * k.c2); // eq. 17
    r.forces.axial_N = kn * area * (k.c3 + kf * k.c4);      // eq. 18
    r.forces.radial_N = kn * area * (k.c5 + kf * k.c6);     // eq. 19
    return r;
}

LiDuCalibration calibrateLiDu(const LiDuToolGeometry &tool, const std::vector<ForceMeasurement> &measurements)
{
    LiDuCalibration result;
    if (measurements.empty()) {
        result.diagnostics.push_back(
            makeError(QStringLiteral("measurements"), CuttingModels::tr("no force measurements given")));
        return result;
    }
    const auto rows = static_cast<Eigen::Index>(2 * measurements.size());
    Eigen::MatrixXd a(rows, 2);
    Eigen::VectorXd y(rows);
    for (std::size_t i = 0; i < measurements.size(); ++i) {
        const ForceMeasurement &m = measurements[i];
        const double area = liDuUncutChipArea_mm2(m.feed_mm_rev, m.depthOfCut_mm, tool.noseRadius_mm);
        const LiDuFactors k = liDuFactors(tool, liDuEffectiveLeadAngle_rad(tool, m.feed_mm_rev, m.depthOfCut_mm));
        const auto r = static_cast<Eigen::Index>(2 * i);
        a.row(r) << area * k.c1, area * k.c2;
        a.row(r + 1) << area * k.c3, area * k.c4;
        y(r) = m.tangential_N;
        y(r + 1) = m.axial_N;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    if (qr.rank() < 2) {
        result.diagnostics.push_back(makeError(
            QStringLiteral("measurements"),
            CuttingModels::tr("the measurements do not determine K_n and K_f (rank %1 of 2)").arg(qr.rank())));
        return result;
    }
    const Eigen::Vector2d pq = qr.solve(y);
    if (pq(0) <= 0.0) {
        result.diagnostics.push_back(
            makeError(QStringLiteral("measurements"),
                      CuttingModels::tr(
                          "the fitted normal pressure K_n = %1 N/mm² is not positive: check the measured forces and "
                          "the tool angles")
                          .arg(num(pq(0)))));
        return result;
    }
    result.coefficients = LiDuCoefficients{pq(0), pq(1) / pq(0)};
    result.rmsResidual_N = std::sqrt((a * pq - y).squaredNorm() / static_cast<double>(rows));
    return result;
}

} // namespace tolturn
