// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/milling/ball_end_forces.h"

#include <Eigen/Geometry>
#include <QCoreApplication>
#include <QLocale>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tolturn {

namespace {

struct BallEndMilling {
    Q_DECLARE_TR_FUNCTIONS(BallEndMilling)
};

// One disc element of the edge at height z (001 §2.1), with what does not change as the tool turns.
struct Slice {
    double z_mm = 0.0;
    double radius_mm = 0.0; // R(z), eq. 2/4
    double sinKappa = 0.0;  // κ: the angle between the tool axis and the ball's normal, eq. 9
    double cosKappa = 0.0;
    double chipWidth_mm = 0.0;  // db = dz / sin κ, eq. 10
    double edgeLength_mm = 0.0; // dS, the length of edge in the element
    double lag_rad = 0.0;       // ψ = z tan i0 / R_o, from eq. 1 with tan i(ψ) = R(ψ) tan i0 / R_o
};

// dS = sqrt(dx² + dy² + dz²) along the helical edge x = R sin(φ − ψ), y = R cos(φ − ψ): with
// R' = (R_o − z) / R and ψ' = tan i0 / R_o, dS = dz sqrt(1 + R'² + R² ψ'²), and 1 + R'² = 1 / sin²κ.
double edgeLength_mm(double dz_mm, double sinKappa, double tanHelix)
{
    const double lagTerm = sinKappa * tanHelix;
    return dz_mm * std::sqrt(1.0 / (sinKappa * sinKappa) + lagTerm * lagTerm);
}

std::vector<Slice> elementsOfTheEdge(const BallEndMill &mill, const BallEndCut &cut, int count)
{
    const double ballRadius = 0.5 * mill.diameter_mm;
    const double tanHelix = std::tan(mill.helix_rad);
    const BallEndBand band = engagedBand(mill, cut);
    const double dz = (band.high_mm - band.low_mm) / count;
    std::vector<Slice> result(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        Slice &s = result[static_cast<std::size_t>(k)];
        s.z_mm = band.low_mm + (k + 0.5) * dz;
        s.radius_mm = localRadius_mm(ballRadius, s.z_mm);
        s.sinKappa = s.radius_mm / ballRadius;
        s.cosKappa = (ballRadius - s.z_mm) / ballRadius;
        s.chipWidth_mm = dz / s.sinKappa;
        s.edgeLength_mm = edgeLength_mm(dz, s.sinKappa, tanHelix);
        s.lag_rad = s.z_mm * tanHelix / ballRadius;
    }
    return result;
}

// Whether a point of the ball, at (X, Y) in the workpiece frame and `height` above the ball's
// lowest point along N, is in the cut. Tables 1 and 2 written as the material's boundaries: an
// element angle φ_WCS lies in [π − acos(q), π] exactly where cos φ_WCS ≤ −q, that is Y ≤ −q R(Z),
// and the front half [0, π] is X ≥ 0. Uncut material (table 1) ends at the plane Y = s − R(a),
// the previous pass (table 2) at the cylinder Y = s − R(Z) it swept; a slot is bounded only by a.
// Up milling mirrors Y.
bool inCut(const BallEndCut &cut, double ballRadius, double wallRadius, double x, double y, double height)
{
    if (x <= 0.0 || height > cut.axialDepth_mm)
        return false;
    const double side = cut.direction == MillingDirection::Down ? y : -y;
    switch (cut.kind) {
    case BallEndCutKind::Slot:
        return true;
    case BallEndCutKind::SideCut:
        return side <= cut.radialDepth_mm - wallRadius;
    case BallEndCutKind::StepOver:
        return side <= cut.radialDepth_mm - localRadius_mm(ballRadius, height);
    }
    return false;
}

// Eq. 11's forces on the tool in its frame: the radial one against the ball's outward normal
// (sin κ sin φ, sin κ cos φ, −cos κ), the tangential one against the edge's velocity (cos φ, −sin φ,
// 0), the axial one along the meridian towards the tip (−cos κ sin φ, −cos κ cos φ, −sin κ): the
// directions of Lee & Altintas (1996) for the ball-end mill.
Eigen::Vector3d toolFrameForce(const Slice &s, double sinPhi, double cosPhi, double radial, double tangential,
                               double axial)
{
    return {-radial * s.sinKappa * sinPhi - tangential * cosPhi - axial * s.cosKappa * sinPhi,
            -radial * s.sinKappa * cosPhi + tangential * sinPhi - axial * s.cosKappa * cosPhi,
            radial * s.cosKappa - axial * s.sinKappa};
}

// The sum over the edge at one rotation angle, with what does not change as the tool turns.
class ForceSummation {
public:
    ForceSummation(const BallEndMill &mill, const MillingForceCoefficients &k, const BallEndCut &cut, int slices,
                   const BallEndSliceCompliance *compliance)
        : m_k(k)
        , m_cut(cut)
        , m_edge(elementsOfTheEdge(mill, cut, slices))
        , m_compliance(compliance)
        , m_ballRadius(0.5 * mill.diameter_mm)
        , m_wallRadius(localRadius_mm(m_ballRadius, cut.axialDepth_mm))
        , m_toWorkpiece(leadTiltTransform(cut.lead_rad, cut.tilt_rad)) // eq. 6
    {
        if (compliance && compliance->lateral_mm_N.size() != m_edge.size())
            throw std::invalid_argument("ballEndForces: one lateral compliance per slice is needed");
        // The angle of flute j's element at slice k at rotation φ is φ + j·pitch − ψ_k: its sine and
        // cosine come from those of φ and of the fixed offset j·pitch − ψ_k.
        const double pitch = 2.0 * std::numbers::pi / mill.flutes;
        m_offsets.reserve(m_edge.size() * static_cast<std::size_t>(mill.flutes));
        for (int j = 0; j < mill.flutes; ++j)
            for (const Slice &s : m_edge)
                m_offsets.emplace_back(std::sin(j * pitch - s.lag_rad), std::cos(j * pitch - s.lag_rad));
    }

    [[nodiscard]] BallEndForceSample at(double rotation_rad) const
    {
        BallEndForceSample sample;
        sample.rotation_rad = rotation_rad;
        const double sinRotation = std::sin(rotation_rad);
        const double cosRotation = std::cos(rotation_rad);
        const std::size_t slices = m_edge.size();
        for (std::size_t e = 0; e < m_offsets.size(); e += slices)
            for (std::size_t k = 0; k < slices; ++k) {
                const Eigen::Vector2d &offset = m_offsets[e + k];
                addElement(k, sinRotation * offset.y() + cosRotation * offset.x(),
                           cosRotation * offset.y() - sinRotation * offset.x(), sample);
            }
        sample.workpieceFrame_N = m_toWorkpiece * sample.toolFrame_N;
        return sample;
    }

private:
    void addElement(std::size_t k, double sinPhi, double cosPhi, BallEndForceSample &sample) const
    {
        const Slice &s = m_edge[k];
        // The element's point from the ball's centre, tool frame (001 fig. 1), then workpiece frame.
        const Eigen::Vector3d point =
            m_toWorkpiece * Eigen::Vector3d(s.radius_mm * sinPhi, s.radius_mm * cosPhi, s.z_mm - m_ballRadius);
        if (!inCut(m_cut, m_ballRadius, m_wallRadius, point.x(), point.y(), point.z() + m_ballRadius))
            return;
        // t = f_t sin φ_WCS sin κ_WCS (eq. 8): the feed along F times the F component of the ball's
        // unit normal, which is X / R_o; db and dS are the element's (eq. 10).
        const double widthPerFeed = point.x() / m_ballRadius * s.chipWidth_mm;
        const Eigen::Vector3d edgeForce =
            toolFrameForce(s, sinPhi, cosPhi, m_k.radialEdge_N_mm * s.edgeLength_mm,
                           m_k.tangentialEdge_N_mm * s.edgeLength_mm, m_k.axialEdge_N_mm * s.edgeLength_mm);
        const Eigen::Vector3d cuttingPerFeed =
            toolFrameForce(s, sinPhi, cosPhi, m_k.radialCutting_N_mm2 * widthPerFeed,
                           m_k.tangentialCutting_N_mm2 * widthPerFeed, m_k.axialCutting_N_mm2 * widthPerFeed);
        const Eigen::Vector3d element = edgeForce + m_cut.feedPerTooth_mm * cuttingPerFeed;
        sample.toolFrame_N += element;
        sample.torque_N_mm += s.radius_mm * (m_k.tangentialEdge_N_mm * s.edgeLength_mm +
                                             m_k.tangentialCutting_N_mm2 * m_cut.feedPerTooth_mm * widthPerFeed);
        if (m_compliance) {
            const double lateral = m_compliance->lateral_mm_N[k];
            const Eigen::Vector3d weights(lateral, lateral, m_compliance->axial_mm_N);
            sample.deflection_mm += weights.cwiseProduct(element);
            sample.deflectionPerFeed_mm_mm += weights.cwiseProduct(cuttingPerFeed);
        }
    }

    const MillingForceCoefficients &m_k;
    const BallEndCut &m_cut;
    std::vector<Slice> m_edge;
    const BallEndSliceCompliance *m_compliance;
    double m_ballRadius;
    double m_wallRadius;
    Eigen::Matrix3d m_toWorkpiece;
    std::vector<Eigen::Vector2d> m_offsets; // (sin, cos) per flute and slice
};

std::string text(const QString &message)
{
    return message.toStdString();
}

} // namespace

std::optional<MillingForceCoefficients> parseMillingCoefficients(const QString &text)
{
    const QStringList parts = text.split(text.contains(QLatin1Char(';')) ? QLatin1Char(';') : QLatin1Char(','));
    if (parts.size() != 6)
        return std::nullopt;
    double v[6] = {0, 0, 0, 0, 0, 0};
    // With semicolons the numbers are the user's locale's first ("1.500" is 1500 in German).
    const bool localeFirst = text.contains(QLatin1Char(';'));
    for (int i = 0; i < 6; ++i) {
        const QString part = parts.at(i).trimmed();
        bool ok = false;
        v[i] = localeFirst ? QLocale().toDouble(part, &ok) : part.toDouble(&ok);
        if (!ok)
            v[i] = localeFirst ? part.toDouble(&ok) : QLocale().toDouble(part, &ok);
        if (!ok || !std::isfinite(v[i]) || std::abs(v[i]) > kMaxMillingCoefficient)
            return std::nullopt;
    }
    return MillingForceCoefficients{v[0], v[1], v[2], v[3], v[4], v[5]};
}

double toolAxisInclination_rad(double lead_rad, double tilt_rad)
{
    return std::acos(std::clamp(std::cos(lead_rad) * std::cos(tilt_rad), -1.0, 1.0));
}

double deepestCutOnBall_mm(double diameter_mm, double lead_rad, double tilt_rad)
{
    return 0.5 * diameter_mm * (1.0 - std::sin(toolAxisInclination_rad(lead_rad, tilt_rad)));
}

BallEndBand engagedBand(const BallEndMill &mill, const BallEndCut &cut)
{
    // The cut is the cap of the ball within a of its lowest point along N: the cone of half angle
    // γ = acos(1 − a / R_o) about that point's direction, which is θ from the tool axis.
    const double ballRadius = 0.5 * mill.diameter_mm;
    const double theta = toolAxisInclination_rad(cut.lead_rad, cut.tilt_rad);
    const double gamma = std::acos(std::clamp(1.0 - cut.axialDepth_mm / ballRadius, -1.0, 1.0));
    const double halfPi = 0.5 * std::numbers::pi;
    return {ballRadius * (1.0 - std::cos(std::max(0.0, theta - gamma))),
            ballRadius * (1.0 - std::cos(std::min(halfPi, theta + gamma)))};
}

std::vector<double> sliceHeights_mm(const BallEndMill &mill, const BallEndCut &cut, const BallEndResolution &resolution)
{
    std::vector<double> heights;
    heights.reserve(static_cast<std::size_t>(resolution.axialSlices));
    for (const Slice &s : elementsOfTheEdge(mill, cut, resolution.axialSlices))
        heights.push_back(s.z_mm);
    return heights;
}

std::vector<std::string> validateBallEndCut(const BallEndMill &mill, const BallEndCut &cut,
                                            const BallEndResolution &resolution)
{
    std::vector<std::string> problems;
    const auto deg = [](double rad) { return rad * 180.0 / std::numbers::pi; };
    if (!(mill.diameter_mm > 0.0))
        problems.push_back(
            text(BallEndMilling::tr("tool diameter: %1 mm is not a positive diameter").arg(mill.diameter_mm)));
    if (mill.flutes < 1 || mill.flutes > 12)
        problems.push_back(text(BallEndMilling::tr("flutes: %1 is not 1 to 12").arg(mill.flutes)));
    if (!(mill.helix_rad >= 0.0 && mill.helix_rad < std::numbers::pi / 3.0))
        problems.push_back(text(BallEndMilling::tr("helix angle: %1° is not 0 to 60°").arg(deg(mill.helix_rad))));
    if (!(cut.feedPerTooth_mm > 0.0))
        problems.push_back(text(BallEndMilling::tr("feed per tooth: %1 mm is not positive").arg(cut.feedPerTooth_mm)));
    if (!(std::abs(cut.lead_rad) <= std::numbers::pi / 3.0) || !(std::abs(cut.tilt_rad) <= std::numbers::pi / 3.0))
        problems.push_back(text(BallEndMilling::tr("lead, tilt: %1°, %2° are not within ±60°")
                                    .arg(deg(cut.lead_rad))
                                    .arg(deg(cut.tilt_rad))));
    if (cut.kind != BallEndCutKind::Slot && !(cut.radialDepth_mm > 0.0))
        problems.push_back(text(BallEndMilling::tr("radial depth: %1 mm is not positive").arg(cut.radialDepth_mm)));
    if (resolution.axialSlices < 1 || resolution.axialSlices > 100000)
        problems.push_back(text(BallEndMilling::tr("axial slices: %1 is not 1 to 100000").arg(resolution.axialSlices)));
    if (resolution.anglesPerRevolution < 1 || resolution.anglesPerRevolution > 100000)
        problems.push_back(text(
            BallEndMilling::tr("angles per revolution: %1 is not 1 to 100000").arg(resolution.anglesPerRevolution)));
    if (problems.empty()) {
        const double deepest = deepestCutOnBall_mm(mill.diameter_mm, cut.lead_rad, cut.tilt_rad);
        if (!(cut.axialDepth_mm > 0.0 && cut.axialDepth_mm <= deepest))
            problems.push_back(
                text(BallEndMilling::tr("axial depth: %1 mm is not within the ball, 0 to %2 mm at lead %3° and "
                                        "tilt %4° (001 models the ball only)")
                         .arg(cut.axialDepth_mm)
                         .arg(deepest, 0, 'f', 3)
                         .arg(deg(cut.lead_rad))
                         .arg(deg(cut.tilt_rad))));
    }
    return problems;
}

std::vector<BallEndForceSample> ballEndForces(const BallEndMill &mill, const MillingForceCoefficients &coefficients,
                                              const BallEndCut &cut, const BallEndResolution &resolution,
                                              const BallEndSliceCompliance *compliance)
{
    if (const std::vector<std::string> problems = validateBallEndCut(mill, cut, resolution); !problems.empty())
        throw std::invalid_argument(problems.front());
    const ForceSummation summation(mill, coefficients, cut, resolution.axialSlices, compliance);
    std::vector<BallEndForceSample> samples;
    samples.reserve(static_cast<std::size_t>(resolution.anglesPerRevolution));
    for (int m = 0; m < resolution.anglesPerRevolution; ++m)
        samples.push_back(summation.at(2.0 * std::numbers::pi * m / resolution.anglesPerRevolution));
    return samples;
}

BallEndForceSummary summarise(const std::vector<BallEndForceSample> &samples)
{
    BallEndForceSummary summary;
    for (const BallEndForceSample &s : samples) {
        summary.peak_N = summary.peak_N.cwiseMax(s.workpieceFrame_N.cwiseAbs());
        summary.peakResultant_N = std::max(summary.peakResultant_N, s.workpieceFrame_N.norm());
        summary.peakTorque_N_mm = std::max(summary.peakTorque_N_mm, s.torque_N_mm);
        summary.meanTorque_N_mm += s.torque_N_mm;
    }
    if (!samples.empty())
        summary.meanTorque_N_mm /= static_cast<double>(samples.size());
    return summary;
}

double spindlePower_W(double meanTorque_N_mm, double spindle_rpm)
{
    // P = T ω, T in N·m, ω = 2π n / 60.
    return meanTorque_N_mm * 1e-3 * 2.0 * std::numbers::pi * spindle_rpm / 60.0;
}

} // namespace tolturn
