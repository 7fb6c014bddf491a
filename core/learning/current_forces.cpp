// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/current_forces.h"

#include "core/io/measurement_table.h"
#include "core/learning/rbf_json.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <cmath>
#include <limits>
#include <numbers>

namespace tolturn {

namespace {

struct CurrentForces {
    Q_DECLARE_TR_FUNCTIONS(CurrentForces)
};

QString num(double v)
{
    return formatNumber(v);
}

constexpr Eigen::Index kTangentialInputs = DriveReading::kTangentialInputs; // ΔI_s, ω_s, ω̇_s (eq. 11)
constexpr Eigen::Index kAxialInputs = DriveReading::kAxialInputs;           // ΔI_a, f_as (eq. 13)

// The inputs' names in JSON and in the warnings, in the networks' order.
const char *const kTangentialNames[] = {"spindle_cutting_current_A", "spindle_speed_rad_s",
                                        "spindle_acceleration_rad_s2"};
const char *const kAxialNames[] = {"feed_cutting_current_A", "feed_speed_mm_min"};

// Below this |det| of eq. 17–18's matrix (entries are sines and cosines, at most 1 in size) K_n
// and K_f are not determined by F_t and F_a.
constexpr double kSingularDeterminant = 1e-9;

QJsonArray namesJson(const char *const *names, Eigen::Index count)
{
    QJsonArray a;
    for (Eigen::Index i = 0; i < count; ++i)
        a.append(QLatin1String(names[i]));
    return a;
}

bool namesMatch(const QJsonValue &value, const char *const *names, Eigen::Index count)
{
    const QJsonArray a = value.toArray();
    if (!value.isArray() || a.size() != count)
        return false;
    for (Eigen::Index i = 0; i < count; ++i) {
        if (a.at(i).toString() != QLatin1String(names[i]))
            return false;
    }
    return true;
}

// Warnings for the inputs of `x` outside [min, max] of the calibration. Out there a sum of Gaussians
// follows no trend of the data: it falls to zero far away and may run off near the range (wide
// Gaussians with large weights of opposite sign: ΔI_s = 20 A for a calibration up to 12 A gave
// 6750 N where the truth was 1180 N in tst_current_forces).
void rangeWarnings(Diagnostics &out, const Eigen::VectorXd &x, const Eigen::VectorXd &min, const Eigen::VectorXd &max,
                   const char *const *names)
{
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        if (x[i] >= min[i] && x[i] <= max[i])
            continue;
        out.push_back(makeWarning(
            QStringLiteral("drive.") + QLatin1String(names[i]),
            CurrentForces::tr("%1 = %2 is outside the range %3 to %4 of the calibration cuts: the network extrapolates")
                .arg(QLatin1String(names[i]), num(x[i]), num(min[i]), num(max[i]))));
    }
}

} // namespace

// Eq. 17 and 18 solved for K_n and K_f, in closed form.
//
// Eq. 17: F_t = K_n A_c [cos α_b cos α + K_f (cos γ_Le sin α + sin γ_Le sin α_b)]
// Eq. 18: F_a = K_n A_c (−cos α_b sin α + K_f cos γ_Le cos α)
// Eq. 19: F_r = K_n A_c (−sin α_b + K_f sin γ_Le cos α_b)
//
// With p = K_n A_c and q = K_n K_f A_c both are linear in (p, q):
//   F_t = c1 p + c2 q,   c1 = cos α_b cos α,    c2 = cos γ_Le sin α + sin γ_Le sin α_b
//   F_a = c3 p + c4 q,   c3 = −cos α_b sin α,   c4 = cos γ_Le cos α
//   F_r = c5 p + c6 q,   c5 = −sin α_b,         c6 = sin γ_Le cos α_b
// By Cramer's rule, with D = c1 c4 − c2 c3
//   = cos α_b cos γ_Le cos²α + cos α_b sin α (cos γ_Le sin α + sin γ_Le sin α_b)
//   = cos α_b (cos γ_Le + sin α sin α_b sin γ_Le),
//   p = (c4 F_t − c2 F_a) / D,   q = (c1 F_a − c3 F_t) / D,
// and so K_n = p / A_c, K_f = q / p (p > 0 needed: K_n > 0), F_r = c5 p + c6 q.
// D = 0 for α_b = ±90°, or where tan γ_Le = −1 / (sin α sin α_b), which needs |γ_Le| > 45°.
// F_r depends on F_t, F_a and the angles only: A_c (eq. 16) scales K_n and cancels in F_r.
std::optional<LiDuInversion> solveLiDuCoefficients(double tangential_N, double axial_N, double uncutChipArea_mm2,
                                                   double backRake_rad, double normalRake_rad,
                                                   double effectiveLeadAngle_rad, QString *error)
{
    const auto refuse = [error](const QString &why) -> std::optional<LiDuInversion> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    for (const double v :
         {tangential_N, axial_N, uncutChipArea_mm2, backRake_rad, normalRake_rad, effectiveLeadAngle_rad}) {
        if (!std::isfinite(v))
            return refuse(CurrentForces::tr("a force, the chip area or an angle is not a finite number"));
    }
    if (!(uncutChipArea_mm2 > 0.0))
        return refuse(CurrentForces::tr("the uncut chip area A_c = %1 mm² (eq. 16) is not above zero")
                          .arg(num(uncutChipArea_mm2)));
    const double sa = std::sin(normalRake_rad), ca = std::cos(normalRake_rad);
    const double sb = std::sin(backRake_rad), cb = std::cos(backRake_rad);
    const double sg = std::sin(effectiveLeadAngle_rad), cg = std::cos(effectiveLeadAngle_rad);
    const double c1 = cb * ca;                   // eq. 17, K_n A_c term
    const double c2 = cg * sa + sg * sb;         // eq. 17, K_n K_f A_c term
    const double c3 = -cb * sa;                  // eq. 18, K_n A_c term
    const double c4 = cg * ca;                   // eq. 18, K_n K_f A_c term
    const double c5 = -sb;                       // eq. 19, K_n A_c term
    const double c6 = sg * cb;                   // eq. 19, K_n K_f A_c term
    const double det = cb * (cg + sa * sb * sg); // = c1 c4 − c2 c3, see above
    if (!(std::abs(det) >= kSingularDeterminant))
        return refuse(CurrentForces::tr("eq. 17 and 18 do not determine K_n and K_f for back rake %1°, normal rake "
                                        "%2° and effective lead angle %3° (determinant %4)")
                          .arg(num(backRake_rad * 180.0 / std::numbers::pi),
                               num(normalRake_rad * 180.0 / std::numbers::pi),
                               num(effectiveLeadAngle_rad * 180.0 / std::numbers::pi), num(det)));
    const double p = (c4 * tangential_N - c2 * axial_N) / det; // K_n A_c
    const double q = (c1 * axial_N - c3 * tangential_N) / det; // K_n K_f A_c
    if (!(p > 0.0))
        return refuse(CurrentForces::tr("F_t = %1 N and F_a = %2 N give a normal pressure K_n = %3 N/mm² that is not "
                                        "positive (eq. 17–18): check the forces and the tool angles")
                          .arg(num(tangential_N), num(axial_N), num(p / uncutChipArea_mm2)));
    LiDuInversion r;
    r.coefficients.normalPressure_MPa = p / uncutChipArea_mm2; // eq. 15a: K_n = N / A_c
    r.coefficients.frictionRatio = q / p;                      // eq. 15b: K_f = P / N
    r.radial_N = c5 * p + c6 * q;                              // eq. 19
    return r;
}

CuttingForceEstimate CurrentForceModel::estimate(const DriveReading &drive, const ToolAngles &tool, double feed_mm_rev,
                                                 double depth_mm, double noseRadius_mm) const
{
    CuttingForceEstimate e;
    e.diagnostics = validateDriveReading(drive, QStringLiteral("drive"));
    const auto positive = [&e](const char *name, double v) {
        if (!(std::isfinite(v) && v > 0.0))
            e.diagnostics.push_back(makeError(
                QLatin1String(name), CurrentForces::tr("%1 = %2 is not above zero").arg(QLatin1String(name), num(v))));
    };
    positive("feed_mm_rev", feed_mm_rev);
    positive("depth_of_cut_mm", depth_mm);
    if (!(std::isfinite(noseRadius_mm) && noseRadius_mm >= 0.0))
        e.diagnostics.push_back(
            makeError(QStringLiteral("tool.nose_radius_mm"),
                      CurrentForces::tr("the nose radius %1 mm is negative or not a number").arg(num(noseRadius_mm))));
    const auto angle = [&e](const char *name, double v, double lo_deg, double hi_deg) {
        const double deg = v * 180.0 / std::numbers::pi;
        if (!(std::isfinite(v) && deg > lo_deg && deg < hi_deg))
            e.diagnostics.push_back(
                makeError(QLatin1String(name), CurrentForces::tr("%1 = %2° is not between %3° and %4°")
                                                   .arg(QLatin1String(name), num(deg), num(lo_deg), num(hi_deg))));
    };
    angle("tool.normal_rake", tool.normalRake_rad, -90.0, 90.0);
    angle("tool.back_rake", tool.backRake_rad, -90.0, 90.0);
    angle("tool.entering_angle", tool.enteringAngle_rad, 0.0, 180.0);
    if (tangential.weights.size() == 0 || axial.weights.size() == 0 || tangentialInputMax.size() != kTangentialInputs ||
        axialInputMax.size() != kAxialInputs)
        e.diagnostics.push_back(
            makeError(QStringLiteral("model"), CurrentForces::tr("the current–force model has not been trained")));
    if (hasErrors(e.diagnostics))
        return e;

    const Eigen::VectorXd xt = drive.tangentialInputs();
    const Eigen::VectorXd xa = drive.axialInputs();
    rangeWarnings(e.diagnostics, xt, tangential.inputMin, tangentialInputMax, kTangentialNames);
    rangeWarnings(e.diagnostics, xa, axial.inputMin, axialInputMax, kAxialNames);
    const double ft = tangential.predict(xt); // eq. 11
    const double fa = axial.predict(xa);      // eq. 13

    e.uncutChipArea_mm2 = liDuUncutChipArea_mm2(feed_mm_rev, depth_mm, noseRadius_mm); // eq. 16a/16b
    // γ_Le by eq. 20 (tan γ_Le = 0.5053 tan γ_L + 1.0473 f/r_n + 0.4654 r_n/d, γ_L = 90° − κ_r);
    // without a nose radius γ_Le = γ_L, the paper's limit of deep cuts (d/r_n large).
    e.effectiveLeadAngle_rad =
        0.5 * std::numbers::pi -
        equivalentEnteringAngle_rad(tool.enteringAngle_rad, noseRadius_mm, feed_mm_rev, depth_mm, &e.diagnostics);
    QString why;
    const auto solved = solveLiDuCoefficients(ft, fa, e.uncutChipArea_mm2, tool.backRake_rad, tool.normalRake_rad,
                                              e.effectiveLeadAngle_rad, &why);
    if (!solved) {
        e.diagnostics.push_back(makeError(
            QStringLiteral("forces"),
            CurrentForces::tr("the radial force cannot be found from the estimated F_t = %1 N and F_a = %2 N: %3")
                .arg(num(ft), num(fa), why)));
        return e;
    }
    e.coefficients = solved->coefficients;
    if (solved->coefficients.frictionRatio < 0.0)
        e.diagnostics.push_back(
            makeWarning(QStringLiteral("forces"),
                        CurrentForces::tr("the friction ratio K_f = %1 found from F_t = %2 N and F_a = %3 N is "
                                          "negative: the friction on the rake face would push the chip down it")
                            .arg(num(solved->coefficients.frictionRatio), num(ft), num(fa))));
    e.forces = CuttingForces{ft, fa, solved->radial_N};
    return e;
}

RbfTrainingOptions currentForceTrainingOptions()
{
    RbfTrainingOptions options;
    options.radiusScales = {1.0, 2.0, 4.0, 8.0, 16.0, 32.0};
    return options;
}

std::optional<CurrentForceModel> trainCurrentForceModel(const std::vector<ForceCalibrationSample> &samples,
                                                        const RbfTrainingOptions &options, QString *error)
{
    const auto refuse = [error](const QString &why) -> std::optional<CurrentForceModel> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    const auto p = static_cast<Eigen::Index>(samples.size());
    if (p < kMinForceCalibrationSamples)
        return refuse(
            CurrentForces::tr("samples: %1 calibration cuts; at least %2 are needed (the paper trained on 21)")
                .arg(p)
                .arg(kMinForceCalibrationSamples));
    Eigen::MatrixXd xt(p, kTangentialInputs);
    Eigen::MatrixXd xa(p, kAxialInputs);
    Eigen::VectorXd ft(p);
    Eigen::VectorXd fa(p);
    for (Eigen::Index i = 0; i < p; ++i) {
        const ForceCalibrationSample &s = samples[static_cast<std::size_t>(i)];
        const QString prefix = QStringLiteral("samples[%1]").arg(i);
        const Diagnostics bad = validateDriveReading(s.drive, prefix + QStringLiteral(".drive"));
        if (!bad.empty())
            return refuse(bad.front().field + QStringLiteral(": ") + bad.front().message);
        if (!std::isfinite(s.tangential_N))
            return refuse(prefix + QStringLiteral(".tangential_N: ") +
                          CurrentForces::tr("the measured tangential force is not a finite number"));
        if (!std::isfinite(s.axial_N))
            return refuse(prefix + QStringLiteral(".axial_N: ") +
                          CurrentForces::tr("the measured axial force is not a finite number"));
        xt.row(i) = s.drive.tangentialInputs().transpose();
        xa.row(i) = s.drive.axialInputs().transpose();
        ft[i] = s.tangential_N;
        fa[i] = s.axial_N;
    }
    CurrentForceModel model;
    QString why;
    auto tangential = trainHybridRbf(xt, ft, options, &why); // eq. 11
    if (!tangential)
        return refuse(CurrentForces::tr("tangential network (eq. 11): %1").arg(why));
    auto axial = trainHybridRbf(xa, fa, options, &why); // eq. 13
    if (!axial)
        return refuse(CurrentForces::tr("axial network (eq. 13): %1").arg(why));
    model.tangential = std::move(*tangential);
    model.axial = std::move(*axial);
    model.tangentialInputMax = xt.colwise().maxCoeff().transpose();
    model.axialInputMax = xa.colwise().maxCoeff().transpose();
    model.samples = static_cast<int>(p);
    return model;
}

std::optional<std::vector<ForceCalibrationSample>> readForceCalibration(const QString &path, Diagnostics &out)
{
    static const std::vector<MeasurementColumn> columns{{"spindle_current_A"},
                                                        {"spindle_idle_current_A"},
                                                        {"spindle_friction_current_A"},
                                                        {"spindle_speed_rad_s"},
                                                        {"spindle_acceleration_rad_s2"},
                                                        {"feed_current_A"},
                                                        {"feed_idle_current_A"},
                                                        {"feed_speed_mm_min"},
                                                        {"tangential_N"},
                                                        {"axial_N"}};
    const auto rows = readMeasurementTable(path, columns, out);
    if (!rows)
        return std::nullopt;
    std::vector<ForceCalibrationSample> samples;
    for (const MeasurementRow &r : *rows) {
        ForceCalibrationSample c;
        c.drive = {*r[0], *r[1], *r[2], *r[3], *r[4], *r[5], *r[6], *r[7]};
        c.tangential_N = *r[8];
        c.axial_N = *r[9];
        samples.push_back(c);
    }
    return samples;
}

QJsonObject currentForceModelJson(const CurrentForceModel &model)
{
    return {{QStringLiteral("samples"), model.samples},
            {QStringLiteral("tangential"),
             QJsonObject{{QStringLiteral("inputs"), namesJson(kTangentialNames, kTangentialInputs)},
                         {QStringLiteral("input_max"), vectorJson(model.tangentialInputMax)},
                         {QStringLiteral("network"), rbfNetworkJson(model.tangential, QStringLiteral("N"))}}},
            {QStringLiteral("axial"),
             QJsonObject{{QStringLiteral("inputs"), namesJson(kAxialNames, kAxialInputs)},
                         {QStringLiteral("input_max"), vectorJson(model.axialInputMax)},
                         {QStringLiteral("network"), rbfNetworkJson(model.axial, QStringLiteral("N"))}}}};
}

std::optional<CurrentForceModel> currentForceModelFromJson(const QJsonObject &json, QString *error)
{
    const auto refuse = [error](const QString &field) -> std::optional<CurrentForceModel> {
        if (error)
            *error = CurrentForces::tr("the current–force model has no valid \"%1\"").arg(field);
        return std::nullopt;
    };
    CurrentForceModel model;
    const QJsonValue samples = json.value(QStringLiteral("samples"));
    if (!samples.isDouble() || samples.toDouble() < 0.0 || samples.toDouble() != std::floor(samples.toDouble()))
        return refuse(QStringLiteral("samples"));
    model.samples = samples.toInt();

    struct Part {
        const char *key;
        const char *const *names;
        Eigen::Index inputs;
        RbfNetwork *network;
        Eigen::VectorXd *inputMax;
    };

    const Part parts[] = {
        {"tangential", kTangentialNames, kTangentialInputs, &model.tangential, &model.tangentialInputMax},
        {"axial", kAxialNames, kAxialInputs, &model.axial, &model.axialInputMax}};
    for (const Part &part : parts) {
        const QString key = QLatin1String(part.key);
        const QJsonObject o = json.value(key).toObject();
        if (!namesMatch(o.value(QStringLiteral("inputs")), part.names, part.inputs))
            return refuse(key + QStringLiteral(".inputs"));
        QString field;
        auto net =
            rbfNetworkFromJson(o.value(QStringLiteral("network")).toObject(), part.inputs, QStringLiteral("N"), field);
        if (!net)
            return refuse(key + QStringLiteral(".network.") + field);
        const auto max = vectorFromJson(o.value(QStringLiteral("input_max")), part.inputs);
        if (!max || (max->array() < net->inputMin.array()).any())
            return refuse(key + QStringLiteral(".input_max"));
        *part.network = std::move(*net);
        *part.inputMax = *max;
    }
    return model;
}

} // namespace tolturn
