// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/deviation/deviation_model.h"

#include "core/cutting/cutting_quantities.h"
#include "core/mechanics/spindle_chuck.h"
#include "core/part/profile_geometry.h"
#include "core/project/keywords.h"
#include "core/tooling/iso1832.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace tolturn {

namespace {

struct DeviationModel {
    Q_DECLARE_TR_FUNCTIONS(DeviationModel)
};

} // namespace

namespace {

struct NodeIndex {
    std::vector<double> nodes;

    std::size_t at(double z) const
    {
        const auto it = std::lower_bound(nodes.begin(), nodes.end(), z - 1e-9);
        return static_cast<std::size_t>(std::distance(nodes.begin(), it));
    }
};

// Stations of a feature inside the supported length, evenly spaced, ends included.
std::vector<double> featureStations(const Segment &s, double zMin, double zMax, int count)
{
    const double a = std::max(s.from.z_mm, zMin);
    const double b = std::min(s.to.z_mm, zMax);
    std::vector<double> z;
    if (b - a <= kProfileEpsilon_mm)
        return z;
    const int n = std::max(count, 2);
    for (int i = 0; i < n; ++i)
        z.push_back(a + (b - a) * i / (n - 1));
    return z;
}

struct Sweeps {
    std::vector<NodeInfluence> radial;
    std::vector<NodeInfluence> tangential;
};

Sweeps sweep(const NodeIndex &index, const std::vector<BeamElementStiffness> &uncut,
             const std::vector<BeamElementStiffness> &finished, const TurningInputs &in)
{
    MovingLoadBeam beam;
    beam.nodes_mm = index.nodes;
    beam.uncut = uncut;
    beam.finished = finished;
    beam.left = in.radialLeft;
    beam.right = in.radialRight;
    Sweeps s;
    s.radial = movingLoadInfluence(beam);
    beam.left = in.tangentialLeft;
    beam.right = in.tangentialRight;
    s.tangential = movingLoadInfluence(beam);
    return s;
}

// Rigid-body motion of the supports carried to the load at z, per unit load in `column`: the
// chuck face's displacement and rotation, or the chord between the two centres.
double supportMotion(const NodeInfluence &n, int column, double z, const TurningInputs &in, bool chuck)
{
    const double x0 = in.supportStart_mm;
    if (chuck)
        return n.leftSupport(0, column) + n.leftSupport(1, column) * (z - x0);
    const double span = in.supportEnd_mm - x0;
    return n.leftSupport(0, column) * (in.supportEnd_mm - z) / span + n.rightSupport(0, column) * (z - x0) / span;
}

StationInfluence stationInfluence(const Sweeps &s, std::size_t node, double z, double contactRadius, bool outer,
                                  const TurningInputs &in, bool chuck)
{
    // The feed force (towards the chuck) acts at the contact radius on the tool's side; its moment
    // moves the section towards the tool for an outer surface and away from it for a bore
    // (docs/model.md §4).
    const double momentPerAxial = outer ? -contactRadius : contactRadius;
    const NodeInfluence &r = s.radial[node];
    const NodeInfluence &t = s.tangential[node];
    StationInfluence si;
    si.radialPerRadial_mm_per_N = r.atLoad(0, 0);
    si.radialPerAxial_mm_per_N = r.atLoad(0, 1) * momentPerAxial;
    si.tangentialPerTangential_mm_per_N = t.atLoad(0, 0);
    si.spindlePerRadial_mm_per_N = supportMotion(r, 0, z, in, chuck);
    si.spindlePerAxial_mm_per_N = supportMotion(r, 1, z, in, chuck) * momentPerAxial;
    si.spindleTangential_mm_per_N = supportMotion(t, 0, z, in, chuck);
    si.rotationPerRadial_rad_per_N = r.atLoad(1, 0);
    si.rotationPerAxial_rad_per_N = r.atLoad(1, 1) * momentPerAxial;
    si.rotationPerMoment_rad_per_Nmm = r.atLoad(1, 1);
    return si;
}

// Nodes closer than a micrometre merged (a station on a vertex).
NodeIndex mergedNodes(const std::set<double> &nodeSet)
{
    NodeIndex index;
    for (const double z : nodeSet) {
        if (index.nodes.empty() || z - index.nodes.back() > 1e-6)
            index.nodes.push_back(z);
    }
    return index;
}

// The supports and profile vertices inside them: the nodes every beam of the part has.
std::set<double> supportAndVertexNodes(const SectionAlongZ &section, const TurningInputs &in)
{
    std::set<double> nodeSet{in.supportStart_mm, in.supportEnd_mm};
    for (const double z : section.breakpoints()) {
        if (z > in.supportStart_mm && z < in.supportEnd_mm)
            nodeSet.insert(z);
    }
    return nodeSet;
}

bool heldByChuck(const TurningInputs &in)
{
    return in.radialLeft.fixedRotation || in.radialLeft.stiffness(1, 1) > 0.0;
}

// The beam's corrections (docs/solid-fe.md): the root at the chuck's or collet's face, a hinge at
// every shoulder.
BeamCorrections correctionsOf(const TurningInputs &in)
{
    BeamCorrections c;
    if (!in.beamCorrections)
        return c;
    c.shoulders = true;
    if (heldByChuck(in))
        c.builtInAt_mm = in.supportStart_mm;
    return c;
}

} // namespace

std::vector<StationInfluence> influenceAt(const PartProfile &part, const TurningInputs &in,
                                          const std::vector<double> &z_mm, const std::vector<double> &contactRadius_mm)
{
    const SectionAlongZ finished(part, 0.0, 0.0, in.stockOuter_mm, in.solidInner_mm);
    std::set<double> nodeSet = supportAndVertexNodes(finished, in);
    nodeSet.insert(z_mm.begin(), z_mm.end());
    const NodeIndex index = mergedNodes(nodeSet);
    const std::vector<BeamElementStiffness> elements =
        buildElements(finished, in.material, index.nodes, correctionsOf(in));
    const Sweeps sweeps = sweep(index, elements, elements, in);
    std::vector<StationInfluence> out;
    for (std::size_t i = 0; i < z_mm.size(); ++i)
        out.push_back(
            stationInfluence(sweeps, index.at(z_mm[i]), z_mm[i], contactRadius_mm[i], true, in, heldByChuck(in)));
    return out;
}

InfluenceTable buildInfluenceTable(const PartProfile &part, const TurningInputs &in, int stationsPerFeature,
                                   double allowance_mm)
{
    InfluenceTable table;
    table.toolpostCompliance_mm_per_N = in.toolpostCompliance_mm_per_N;
    const double x0 = in.supportStart_mm;
    const double x1 = in.supportEnd_mm;

    // Nodes: supports, profile vertices and every station.
    const SectionAlongZ finished(part, 0.0, 0.0, in.stockOuter_mm, in.solidInner_mm);
    std::set<double> nodeSet = supportAndVertexNodes(finished, in);
    for (const ContourSide side : {ContourSide::Outer, ContourSide::Inner}) {
        const Contour &contour = part.contour(side);
        for (const Segment &s : contour.segments) {
            if (in.scoped && !in.cutFeatures.contains(s.id))
                continue; // another operation cuts it
            FeatureInfluence f{s.id, side, s.kind, {}, {}, {}};
            if (s.isAxial()) {
                f.z_mm = featureStations(s, x0, x1, stationsPerFeature);
                for (const double z : f.z_mm)
                    f.nominalRadius_mm.push_back(radiusOnSegment(s, z));
                if (!f.z_mm.empty())
                    table.features.push_back(f);
            } else if (s.from.z_mm >= x0 - kProfileEpsilon_mm && s.from.z_mm <= x1 + kProfileEpsilon_mm) {
                f.z_mm = {s.from.z_mm};
                f.nominalRadius_mm = {std::max(s.from.r_mm, s.to.r_mm)};
                table.faces.push_back(f);
            }
            for (const double z : f.z_mm)
                nodeSet.insert(z);
        }
    }
    const NodeIndex index = mergedNodes(nodeSet);
    const std::vector<BeamElementStiffness> finishedElements =
        buildElements(finished, in.material, index.nodes, correctionsOf(in));
    const bool chuck = heldByChuck(in);
    auto sweepsFor = [&](ContourSide side) {
        if (allowance_mm <= 0.0)
            return sweep(index, finishedElements, finishedElements, in);
        const SectionAlongZ uncut(part, side == ContourSide::Outer ? allowance_mm : 0.0,
                                  side == ContourSide::Inner ? allowance_mm : 0.0, in.stockOuter_mm, in.solidInner_mm);
        return sweep(index, buildElements(uncut, in.material, index.nodes, correctionsOf(in)), finishedElements, in);
    };
    const Sweeps outer = sweepsFor(ContourSide::Outer);
    const Sweeps inner = part.inner.empty() ? outer : sweepsFor(ContourSide::Inner);

    for (std::vector<FeatureInfluence> *list : {&table.features, &table.faces}) {
        for (FeatureInfluence &f : *list) {
            const bool isOuter = f.side == ContourSide::Outer;
            const Sweeps &s = isOuter ? outer : inner;
            for (std::size_t i = 0; i < f.z_mm.size(); ++i)
                f.stations.push_back(
                    stationInfluence(s, index.at(f.z_mm[i]), f.z_mm[i], f.nominalRadius_mm[i], isOuter, in, chuck));
        }
    }
    return table;
}

namespace {

// Steady radial drift at a spindle speed (docs/model.md §5): a_n n/1000 + a_T (T - T_ref) [mm].
double steadyDrift_mm(const ThermalDrift &t, const TurningInputs &in, double spindleSpeed_rpm)
{
    return 1e-3 * (t.drift_um_per_1000rpm * spindleSpeed_rpm / 1000.0 +
                   t.drift_um_per_K * (in.ambientTemperature_C - t.referenceTemperature_C));
}

double spindleSpeedAt(const TurningInputs &in, double radius_mm)
{
    double n = spindleSpeed_rpm(in.pass.cuttingSpeed_m_min, 2.0 * radius_mm);
    if (in.maxSpindleSpeed_rpm)
        n = std::min(n, *in.maxSpindleSpeed_rpm);
    return n;
}

// The thermal drift at every station of one contour's features, along the pass (docs/model.md §5):
// the first-order warm-up d(delta)/dt = (delta_ss(n) - delta)/tau integrated as the tool travels
// from the right end towards the chuck, dt = dz / (f n(z)) at constant cutting speed, each step
// with the mean steady drift of its two ends. At the start of the pass the machine has warmed
// for the time since start at the first station's speed: delta_0 = delta_ss (1 - exp(-t0/tau)).
// Returns the drift per feature and station (0 where nothing is characterised).
std::vector<std::vector<double>> thermalAlongPass(const InfluenceTable &table, const TurningInputs &in,
                                                  ContourSide side)
{
    std::vector<std::vector<double>> drift;
    if (!in.thermal)
        return drift; // no drift: nothing to allocate on the optimiser's path
    drift.resize(table.features.size());
    for (std::size_t i = 0; i < table.features.size(); ++i)
        drift[i].assign(table.features[i].z_mm.size(), 0.0);
    const ThermalDrift &t = *in.thermal;

    struct Point {
        std::size_t feature, station;
        double z, n;
    };

    std::vector<Point> points;
    for (std::size_t i = 0; i < table.features.size(); ++i) {
        const FeatureInfluence &f = table.features[i];
        if (f.side != side)
            continue;
        for (std::size_t j = 0; j < f.z_mm.size(); ++j)
            points.push_back({i, j, f.z_mm[j], spindleSpeedAt(in, f.nominalRadius_mm[j])});
    }
    std::stable_sort(points.begin(), points.end(), [](const Point &a, const Point &b) { return a.z > b.z; });
    // On the axis (a pointed cone, a dome) constant cutting speed asks for an infinite spindle speed
    // unless the machine's maximum is known: such a station takes its neighbour's speed.
    for (std::size_t k = 0; k < points.size(); ++k) {
        if (std::isfinite(points[k].n) && points[k].n > 0.0)
            continue;
        const auto finite =
            std::find_if(points.begin(), points.end(), [](const Point &q) { return std::isfinite(q.n) && q.n > 0.0; });
        points[k].n = k > 0 ? points[k - 1].n : (finite != points.end() ? finite->n : 0.0);
    }
    if (points.empty() || !(points.front().n > 0.0))
        return drift;
    double delta = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Point &p = points[k];
        if (k == 0) {
            const double warm =
                t.timeConstant_min > 0.0 ? 1.0 - std::exp(-in.timeSinceStart_min / t.timeConstant_min) : 1.0;
            delta = steadyDrift_mm(t, in, p.n) * warm;
        } else {
            const Point &q = points[k - 1];
            const double dt_min = (q.z - p.z) / in.pass.feed_mm_rev * 0.5 * (1.0 / q.n + 1.0 / p.n);
            const double steady = 0.5 * (steadyDrift_mm(t, in, q.n) + steadyDrift_mm(t, in, p.n));
            const double decay = t.timeConstant_min > 0.0 ? std::exp(-dt_min / t.timeConstant_min) : 0.0;
            delta = steady + (delta - steady) * decay;
        }
        drift[p.feature][p.station] = delta;
    }
    return drift;
}

Station evaluateStation(const StationInfluence &si, double z, double r0, bool outer, const TurningInputs &in,
                        double toolpost, double drift)
{
    const CuttingForces &f = in.forcesOn(outer ? ContourSide::Outer : ContourSide::Inner);
    Station st;
    st.z_mm = z;
    st.nominalRadius_mm = r0;
    st.spindleSpeed_rpm = spindleSpeedAt(in, r0);
    st.radial.spindleChuck_mm = f.radial_N * si.spindlePerRadial_mm_per_N + f.axial_N * si.spindlePerAxial_mm_per_N;
    st.radial.workpiece_mm =
        f.radial_N * si.radialPerRadial_mm_per_N + f.axial_N * si.radialPerAxial_mm_per_N - st.radial.spindleChuck_mm;
    if (!outer && in.boring) {
        // A boring bar lies along the axis: the passive force bends it, it does not shorten it.
        const BoringBarDeflection bar =
            boringBarDeflection(in.boring->bar, in.boring->compliance, f.radial_N, f.tangential_N, f.axial_N);
        st.radial.boringBar_mm = bar.radial_mm;
        st.tangential.boringBar_mm = bar.tangential_mm;
    } else {
        st.radial.toolpost_mm = f.radial_N * toolpost;
    }
    // A drift of the tool away from the axis enlarges shafts and bores alike.
    st.radial.thermal_mm = outer ? drift : -drift;
    st.tangential.spindleChuck_mm = f.tangential_N * si.spindleTangential_mm_per_N;
    st.tangential.workpiece_mm = f.tangential_N * si.tangentialPerTangential_mm_per_N - st.tangential.spindleChuck_mm;
    st.radiusError_mm = radiusError_mm(r0, st.radial.total_mm(), st.tangential.total_mm(), outer);
    st.sectionRotation_rad = f.radial_N * si.rotationPerRadial_rad_per_N + f.axial_N * si.rotationPerAxial_rad_per_N;
    return st;
}

// A face cut by a facing pass (docs/model.md §4). The finishing program follows the contour from
// the right end towards the chuck, so a face that faces the right end (material on its left) is
// cut moving away from where the turned surface on its right ends: an outer face outwards, a bore
// step inwards (a face facing the chuck the other way). The feed force Ff then loads the section
// radially towards the tool (negative as material left), the passive force Fp pushes the part
// away from the tool along the axis, with a moment arm that is the contact radius rho as the tool
// crosses the face. The section at the face turns by
//   theta(rho) = s_F Ff c_theta,F + s_M Fp rho c_theta,M
// and the face point cut at rho is left u(rho) = rho theta(rho) out of its plane; the axial
// run-out e is the range of u over the face (Valiño et al. 2008 eq. 12, e = (D_M - D_m)/2
// tan(theta), when theta does not change across it). tan(theta) reported is the mean tilt.
FaceConicity faceUnderFacingCut(const Segment &s, const FeatureInfluence &f, const TurningInputs &in)
{
    const StationInfluence &si = f.stations.front();
    const bool outer = f.side == ContourSide::Outer;
    const bool facesRightEnd = outer ? s.to.r_mm < s.from.r_mm : s.to.r_mm > s.from.r_mm;
    const double signF = facesRightEnd ? -1.0 : 1.0;
    // As the feed force in turning (towards the chuck): -rho on an outer surface, +rho in a bore.
    const double signM = (outer ? -1.0 : 1.0) * (facesRightEnd ? 1.0 : -1.0);
    const double rIn = std::min(s.from.r_mm, s.to.r_mm);
    const double rOut = std::max(s.from.r_mm, s.to.r_mm);
    const CuttingForces &forces = in.forcesOn(f.side);
    const double a = signF * forces.axial_N * si.rotationPerRadial_rad_per_N;
    const double b = signM * forces.radial_N * si.rotationPerMoment_rad_per_Nmm;
    const auto u = [a, b](double rho) { return rho * (a + b * rho); };
    constexpr int kSamples = 41;
    double lo = u(rIn);
    double hi = lo;
    for (int i = 1; i < kSamples; ++i) {
        const double v = u(rIn + (rOut - rIn) * i / (kSamples - 1));
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    // The extreme of the parabola u(rho) where it lies inside the face.
    if (b != 0.0) {
        const double vertex = -a / (2.0 * b);
        if (vertex > rIn && vertex < rOut) {
            lo = std::min(lo, u(vertex));
            hi = std::max(hi, u(vertex));
        }
    }
    FaceConicity fc;
    fc.featureId = f.featureId;
    fc.side = f.side;
    fc.z_mm = f.z_mm.front();
    fc.tanTheta = rOut > rIn ? (u(rOut) - u(rIn)) / (rOut - rIn) : 0.0;
    fc.axialRunout_mm = hi - lo;
    return fc;
}

} // namespace

DeviationResult evaluateInfluenceTable(const PartProfile &part, const InfluenceTable &table, const TurningInputs &in)
{
    DeviationResult result;
    result.features.reserve(table.features.size());
    const std::vector<std::vector<double>> outerDrift = thermalAlongPass(table, in, ContourSide::Outer);
    const std::vector<std::vector<double>> innerDrift = thermalAlongPass(table, in, ContourSide::Inner);
    for (std::size_t k = 0; k < table.features.size(); ++k) {
        const FeatureInfluence &f = table.features[k];
        FeatureDeviation fd{f.featureId, f.side, f.kind, {}};
        fd.stations.reserve(f.stations.size());
        const bool outer = f.side == ContourSide::Outer;
        const std::vector<std::vector<double>> &drifts = outer ? outerDrift : innerDrift;
        for (std::size_t i = 0; i < f.stations.size(); ++i) {
            const Station st = evaluateStation(f.stations[i], f.z_mm[i], f.nominalRadius_mm[i], outer, in,
                                               table.toolpostCompliance_mm_per_N, drifts.empty() ? 0.0 : drifts[k][i]);
            const double diameter = 2.0 * st.nominalRadius_mm;
            const double speed = std::numbers::pi * diameter * st.spindleSpeed_rpm / 1000.0;
            const double cuttingForce_N = in.forcesOn(f.side).tangential_N;
            result.maxPower_kW = std::max(result.maxPower_kW, cuttingPower_kW(cuttingForce_N, speed));
            result.maxTorque_Nm = std::max(result.maxTorque_Nm, spindleTorque_Nm(cuttingForce_N, diameter));
            fd.stations.push_back(st);
        }
        result.features.push_back(std::move(fd));
    }
    for (const FeatureInfluence &f : table.faces)
        result.faces.push_back(faceUnderFacingCut(*findFeature(part, f.featureId)->segment, f, in));
    // The roughness of the worse surface: a bore cut with the boring bar's insert has its nose radius.
    double noseRadius = in.noseRadius_mm;
    const bool bores = std::any_of(table.features.begin(), table.features.end(),
                                   [](const FeatureInfluence &f) { return f.side == ContourSide::Inner; });
    if (in.boring && bores)
        noseRadius = std::min(noseRadius, in.boring->noseRadius_mm);
    result.theoreticalRa_um = theoreticalRa_um(in.pass.feed_mm_rev, noseRadius);
    result.theoreticalRz_um = theoreticalRz_um(in.pass.feed_mm_rev, noseRadius);
    result.inputs = in;
    return result;
}

double radiusError_mm(double r0, double radial_mm, double tangential_mm, bool outer)
{
    const double rr = outer ? r0 + radial_mm : r0 - radial_mm;
    return std::sqrt(rr * rr + tangential_mm * tangential_mm) - r0;
}

DeviationResult deviationFor(const PartProfile &part, const TurningInputs &in, const DeviationOptions &options)
{
    const double allowance = options.inProcessSection ? in.pass.depthOfCut_mm : 0.0;
    const InfluenceTable table = buildInfluenceTable(part, in, options.stationsPerFeature, allowance);
    return evaluateInfluenceTable(part, table, in);
}

namespace {

// The model is linear: the forces are those of the nominal depth of cut, whatever the part's
// deflection (Valiño et al. 2008 eq. 2: deviation = compliance x force). Where the predicted
// radial deviation exceeds the depth of cut the part would spring out of the cut altogether, the
// real depth and forces are not the modelled ones, and the result says nothing about the part
// (a long shaft in a chuck, say): a warning on the pass, with the largest deviation and where.
void checkSmallDeflection(DeviationResult &result, const TurningInputs &in, const DeviationOptions &options)
{
    if (options.loadOverride)
        return; // given forces: no depth of cut stands behind them
    double worst_mm = 0.0;
    double at_mm = 0.0;
    for (const FeatureDeviation &f : result.features) {
        for (const Station &st : f.stations) {
            if (std::abs(st.radial.total_mm()) > worst_mm) {
                worst_mm = std::abs(st.radial.total_mm());
                at_mm = st.z_mm;
            }
        }
    }
    if (worst_mm > in.pass.depthOfCut_mm)
        result.diagnostics.push_back(makeWarning(
            QStringLiteral("passes"),
            DeviationModel::tr("the predicted deflection, %1 mm at z = %2 mm, is larger than the depth of cut %3 mm: "
                               "the part would spring out of the cut, and a model linear in the forces of the "
                               "nominal depth does not hold; support the part (tailstock, steady rest) or cut less")
                .arg(QString::number(worst_mm, 'f', worst_mm >= 10.0 ? 0 : 3), formatNumber(at_mm),
                     formatNumber(in.pass.depthOfCut_mm))));
}

} // namespace

DeviationResult computeDeviation(const Project &project, const DataLibrary &data, const DeviationOptions &options)
{
    InputsResult resolved = resolveTurningInputs(project, data, options);
    if (!resolved.inputs) {
        DeviationResult failed;
        failed.diagnostics = resolved.diagnostics;
        return failed;
    }
    const TurningInputs &in = *resolved.inputs;
    DeviationResult result = deviationFor(project.part, in, options);
    result.diagnostics = resolved.diagnostics;
    checkSmallDeflection(result, in, options);
    if (in.maxPower_kW && result.maxPower_kW > *in.maxPower_kW)
        result.diagnostics.push_back(
            makeWarning(QStringLiteral("passes"),
                        DeviationModel::tr("the pass needs %1 kW of cutting power, more than the machine's "
                                           "%2 kW")
                            .arg(formatNumber(result.maxPower_kW), formatNumber(*in.maxPower_kW))));
    return result;
}

std::vector<double> sweepFormErrors(const InfluenceTable &table, const std::vector<ConditionForces> &conditions)
{
    // Per station the radial deviation is Fr (c_r + c_tp) + Fa c_a; the spread over a feature is
    // evaluated for every condition from the two coefficient columns.
    std::vector<double> out;
    out.reserve(conditions.size() * table.features.size());
    for (const ConditionForces &c : conditions) {
        for (const FeatureInfluence &f : table.features) {
            double lo = 1e300;
            double hi = -1e300;
            for (const StationInfluence &si : f.stations) {
                const double w = c.radial_N * (si.radialPerRadial_mm_per_N + table.toolpostCompliance_mm_per_N) +
                                 c.axial_N * si.radialPerAxial_mm_per_N;
                lo = std::min(lo, w);
                hi = std::max(hi, w);
            }
            out.push_back(hi - lo);
        }
    }
    return out;
}

} // namespace tolturn
