// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/deviation/stiffness_calibration.h"

#include "core/deviation/deviation_model.h"
#include "core/io/measurement_table.h"

#include <Eigen/Dense>
#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <set>

namespace tolturn {

namespace {

struct SpindleCalibration {
    Q_DECLARE_TR_FUNCTIONS(SpindleCalibration)
};

constexpr int kStations = 401; // stations on each turned feature for the bar's own deflection

// The model's deviation of the bar without the spindle–chuck term, at one z.
struct BarStation {
    double z_mm = 0.0;
    double radius_mm = 0.0;
    double radialOther_mm = 0.0;     // bar bending and toolpost
    double tangentialOther_mm = 0.0; // bar bending
};

std::vector<BarStation> outerStations(const DeviationResult &result)
{
    std::vector<BarStation> stations;
    for (const FeatureDeviation &f : result.features) {
        if (f.side != ContourSide::Outer)
            continue;
        for (const Station &s : f.stations)
            stations.push_back({s.z_mm, s.nominalRadius_mm, s.radial.total_mm() - s.radial.spindleChuck_mm,
                                s.tangential.total_mm() - s.tangential.spindleChuck_mm});
    }
    std::sort(stations.begin(), stations.end(),
              [](const BarStation &a, const BarStation &b) { return a.z_mm < b.z_mm; });
    return stations;
}

// Linear interpolation between the stations around z; nullopt outside the turned length.
std::optional<BarStation> stationAt(const std::vector<BarStation> &stations, double z_mm)
{
    const auto after = std::lower_bound(stations.begin(), stations.end(), z_mm,
                                        [](const BarStation &s, double z) { return s.z_mm < z; });
    if (after == stations.end())
        return std::nullopt;
    if (after->z_mm == z_mm)
        return *after;
    if (after == stations.begin())
        return std::nullopt;
    const BarStation &a = *(after - 1);
    const BarStation &b = *after;
    const double t = (z_mm - a.z_mm) / (b.z_mm - a.z_mm);
    auto lerp = [t](double u, double v) { return u + t * (v - u); };
    return BarStation{z_mm, lerp(a.radius_mm, b.radius_mm), lerp(a.radialOther_mm, b.radialOther_mm),
                      lerp(a.tangentialOther_mm, b.tangentialOther_mm)};
}

QString number(double v)
{
    return QString::number(v, 'g', 4);
}

// The springs of P(x) = a x² + b x + c under the force F and the moment M (docs/model.md §2).
std::optional<SpindleSprings> springsOf(double a, double b, double c, double force_N, double moment_Nmm,
                                        double pivot_mm, const QString &direction, Diagnostics &out)
{
    const double s = a / force_N;                                          // 1/k2 + 1/k3
    const double inv2 = (b - moment_Nmm * s) / (2.0 * force_N * pivot_mm); // from the x term
    const double inv3 = s - inv2;                                          // from the x² term
    const double inv1 = (c - (force_N * pivot_mm * pivot_mm + moment_Nmm * pivot_mm) * inv2) / force_N;
    const std::pair<QString, double> compliances[] = {{QStringLiteral("k1 [N/mm]"), inv1},
                                                      {QStringLiteral("k2 [N·mm/rad]"), inv2},
                                                      {QStringLiteral("k3 [N·mm/rad]"), inv3}};
    bool ok = true;
    for (const auto &[name, inverse] : compliances) {
        if (inverse > 0.0 && std::isfinite(inverse))
            continue;
        ok = false;
        out.push_back(makeError(
            QStringLiteral("measurements"),
            SpindleCalibration::tr("the %1 fit gives %2 = %3, which is not a spring (it must be above zero): the "
                                   "measured deviation does not grow from the chuck as a spindle–chuck held by "
                                   "springs would. Check the measurement, the forces, Lc and that the bar is held "
                                   "in the chuck only")
                .arg(direction, name, inverse == 0.0 ? QStringLiteral("∞") : number(1.0 / inverse))));
    }
    if (!ok)
        return std::nullopt;
    return SpindleSprings{1.0 / inv1, 1.0 / inv2, 1.0 / inv3};
}

// Least-squares P(x) through (x, y) [mm] and the springs it gives.
std::optional<SpringFit> fitDirection(const std::vector<std::pair<double, double>> &xy, double force_N,
                                      double moment_Nmm, double pivot_mm, const QString &direction, Diagnostics &out)
{
    const auto n = static_cast<Eigen::Index>(xy.size());
    Eigen::MatrixXd design(n, 3);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double x = xy[static_cast<std::size_t>(i)].first;
        design.row(i) << x * x, x, 1.0;
        y(i) = xy[static_cast<std::size_t>(i)].second;
    }
    const Eigen::Vector3d p = design.colPivHouseholderQr().solve(y);
    const auto springs = springsOf(p(0), p(1), p(2), force_N, moment_Nmm, pivot_mm, direction, out);
    if (!springs)
        return std::nullopt;
    const double rms_mm = std::sqrt((design * p - y).squaredNorm() / static_cast<double>(n));
    return SpringFit{*springs, p(0), p(1), p(2), 1000.0 * rms_mm, static_cast<int>(n)};
}

// How many different values of z (or x) the points have: the fit needs three.
template <typename Range, typename Position>
std::size_t distinctPositions(const Range &points, Position position)
{
    std::set<double> distinct;
    for (const auto &p : points)
        distinct.insert(position(p));
    return distinct.size();
}

// The same for (x, deviation) pairs of one direction, as the fits take them.
std::size_t distinctPositions(const std::vector<std::pair<double, double>> &xy)
{
    return distinctPositions(xy, [](const std::pair<double, double> &p) { return p.first; });
}

bool checkSetUp(const Project &bar, const std::vector<TestBarPoint> &points, double pivot_mm, Diagnostics &out)
{
    if (bar.clamping.method != ClampingMethod::Chuck)
        out.push_back(makeError(QStringLiteral("clamping.method"),
                                SpindleCalibration::tr("the test bar must be held in the chuck only (Valiño et al. "
                                                       "2008 §III); a centre would carry part of the load")));
    if (!(pivot_mm > 0.0) || !std::isfinite(pivot_mm))
        out.push_back(makeError(QStringLiteral("pivot_distance_mm"),
                                SpindleCalibration::tr("Lc, the distance of the spindle bearing behind the chuck "
                                                       "face, must be above zero, but is %1 mm")
                                    .arg(number(pivot_mm))));
    const std::size_t positions = distinctPositions(points, [](const TestBarPoint &p) { return p.z_mm; });
    if (positions < 3)
        out.push_back(makeError(QStringLiteral("measurements"),
                                SpindleCalibration::tr("the fit of a z² + b z + c needs points at three or more "
                                                       "positions z, but there are %1")
                                    .arg(positions)));
    return !hasErrors(out);
}

const std::vector<MeasurementColumn> &testBarColumns()
{
    static const std::vector<MeasurementColumn> columns{
        {"z_mm", true, false}, {"radial_um", true, false}, {"tangential_um", false, false}};
    return columns;
}

TestBarReadResult testBarPoints(const std::optional<std::vector<MeasurementRow>> &rows, Diagnostics diagnostics)
{
    TestBarReadResult result;
    result.diagnostics = std::move(diagnostics);
    if (!rows)
        return result;
    std::vector<TestBarPoint> points;
    for (const MeasurementRow &r : *rows)
        points.push_back({r[0].value_or(0.0), r[1].value_or(0.0), r[2]});
    result.points = std::move(points);
    return result;
}

// The tangential springs, where the tangential deviation was measured at three positions or more
// under a tangential force; a warning that says why not where it was measured but cannot be fitted.
void fitTangential(const std::vector<std::pair<double, double>> &tangential, StiffnessCalibration &cal)
{
    Diagnostics &out = cal.diagnostics;
    cal.tangentialPositions = static_cast<int>(distinctPositions(tangential));
    if (cal.tangentialPositions == 0)
        return;
    if (cal.tangentialPositions < 3) {
        out.push_back(makeWarning(QStringLiteral("measurements"),
                                  SpindleCalibration::tr("tangential_um is given at %1 positions z; the fit needs "
                                                         "three or more: the tangential springs are not fitted")
                                      .arg(cal.tangentialPositions)));
        return;
    }
    if (!(cal.forces.tangential_N > 0.0)) {
        out.push_back(makeWarning(QStringLiteral("load"),
                                  SpindleCalibration::tr("the tangential force is %1 N: the tangential springs are "
                                                         "not fitted")
                                      .arg(number(cal.forces.tangential_N))));
        return;
    }
    cal.tangential = fitDirection(tangential, cal.forces.tangential_N, 0.0, cal.pivotDistance_mm,
                                  SpindleCalibration::tr("tangential"), out);
}

} // namespace

TestBarReadResult parseTestBarMeasurements(const QString &text, const QString &fileName)
{
    Diagnostics diagnostics;
    const auto rows = parseMeasurementTable(text, fileName, testBarColumns(), diagnostics);
    return testBarPoints(rows, std::move(diagnostics));
}

TestBarReadResult readTestBarMeasurements(const QString &path)
{
    Diagnostics diagnostics;
    const auto rows = readMeasurementTable(path, testBarColumns(), diagnostics);
    return testBarPoints(rows, std::move(diagnostics));
}

StiffnessCalibration calibrateSpindleChuck(const Project &testBar, const DataLibrary &data,
                                           const std::vector<TestBarPoint> &points, double pivotDistance_mm,
                                           const std::optional<CuttingForces> &load)
{
    StiffnessCalibration cal;
    cal.pivotDistance_mm = pivotDistance_mm;
    Diagnostics &out = cal.diagnostics;
    if (!checkSetUp(testBar, points, pivotDistance_mm, out))
        return cal;
    // The bar with a rigid chuck: what remains of the measurement is the spindle–chuck's.
    Project rigid = testBar;
    rigid.characterisation = {};
    DeviationOptions options;
    options.loadOverride = load;
    options.stationsPerFeature = kStations;
    const DeviationResult model = computeDeviation(rigid, data, options);
    out.insert(out.end(), model.diagnostics.begin(), model.diagnostics.end());
    if (!model.inputs)
        return cal;
    cal.forces = model.inputs->forces;
    const std::vector<BarStation> stations = outerStations(model);
    const double chuckFace = testBar.clamping.clampedLength_mm;
    std::vector<std::pair<double, double>> radial;
    std::vector<std::pair<double, double>> tangential;
    std::optional<BarStation> farthest;
    double farthestMeasured_mm = 0.0;
    for (const TestBarPoint &p : points) {
        const auto s = stationAt(stations, p.z_mm);
        if (!s) {
            out.push_back(makeError(
                QStringLiteral("measurements"),
                SpindleCalibration::tr("z = %1 mm is not on the turned outer surface of the bar").arg(number(p.z_mm))));
            continue;
        }
        if (cal.diameter_mm == 0.0)
            cal.diameter_mm = 2.0 * s->radius_mm;
        if (std::abs(2.0 * s->radius_mm - cal.diameter_mm) > 1e-6)
            out.push_back(makeError(QStringLiteral("measurements"),
                                    SpindleCalibration::tr("z = %1 mm lies on Ø%2 mm, but the first point on Ø%3 mm: "
                                                           "the fit needs the bar's points on one diameter")
                                        .arg(number(p.z_mm), number(2.0 * s->radius_mm), number(cal.diameter_mm))));
        const double x = p.z_mm - chuckFace;
        radial.emplace_back(x, 1e-3 * p.radial_um - s->radialOther_mm);
        if (p.tangential_um)
            tangential.emplace_back(x, 1e-3 * *p.tangential_um - s->tangentialOther_mm);
        if (!farthest || p.z_mm > farthest->z_mm) {
            farthest = s;
            farthestMeasured_mm = 1e-3 * p.radial_um;
        }
    }
    if (hasErrors(out))
        return cal;
    if (!(cal.forces.radial_N > 0.0)) {
        out.push_back(makeError(QStringLiteral("load"), SpindleCalibration::tr("the radial force must be above zero, "
                                                                               "but is %1 N")
                                                            .arg(number(cal.forces.radial_N))));
        return cal;
    }
    if (farthestMeasured_mm != 0.0)
        cal.barShareAtEnd = std::abs(farthest->radialOther_mm / farthestMeasured_mm);
    if (cal.barShareAtEnd > 0.5)
        out.push_back(makeWarning(
            QStringLiteral("measurements"),
            SpindleCalibration::tr("the bar's own bending and the toolpost make %1 % of the deviation measured at "
                                   "z = %2 mm: a stiffer (shorter, thicker) bar gives a surer fit")
                .arg(QString::number(100.0 * cal.barShareAtEnd, 'f', 0), number(farthest->z_mm))));
    const double moment = -0.5 * cal.forces.axial_N * cal.diameter_mm; // the feed force at the contact radius
    cal.radial =
        fitDirection(radial, cal.forces.radial_N, moment, pivotDistance_mm, SpindleCalibration::tr("radial"), out);
    // Three positions fit a z² + b z + c exactly: the residual is zero whatever the scatter, and
    // each spring then rests on the measurement's own error (0.1 µm of it moved k1 by half).
    if (distinctPositions(radial) == 3)
        out.push_back(
            makeWarning(QStringLiteral("measurements"),
                        SpindleCalibration::tr("three positions z fit a z² + b z + c exactly: the RMS "
                                               "residual of 0 says nothing of the measurement's scatter, "
                                               "which goes into the springs whole; measure at four or more")));
    fitTangential(tangential, cal);
    // A fit that failed in either direction is no fit: nothing half-measured reaches a project.
    if (hasErrors(out)) {
        cal.radial.reset();
        cal.tangential.reset();
    }
    return cal;
}

QString staleTangentialSprings(const MachineCharacterisation &characterisation, const StiffnessCalibration &cal)
{
    if (cal.tangential || !characterisation.spindleTangential || !characterisation.pivotDistance_mm ||
        *characterisation.pivotDistance_mm == cal.pivotDistance_mm)
        return {};
    return SpindleCalibration::tr("the tangential springs were fitted for Lc = %1 mm and do not hold at Lc = %2 mm: "
                                  "removed; measure the tangential deviation to fit them again")
        .arg(number(*characterisation.pivotDistance_mm), number(cal.pivotDistance_mm));
}

MachineCharacterisation withFittedSprings(MachineCharacterisation characterisation, const StiffnessCalibration &cal,
                                          const QString &source)
{
    if (!staleTangentialSprings(characterisation, cal).isEmpty())
        characterisation.spindleTangential.reset();
    characterisation.pivotDistance_mm = cal.pivotDistance_mm;
    if (cal.radial)
        characterisation.spindleRadial = cal.radial->springs;
    if (cal.tangential)
        characterisation.spindleTangential = cal.tangential->springs;
    characterisation.source = source;
    return characterisation;
}

} // namespace tolturn
