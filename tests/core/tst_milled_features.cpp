// SPDX-License-Identifier: GPL-3.0-or-later
// Milled features of a project (issue 19, docs/milling.md "Milled features"): the lead and tilt of
// a CL point by hand, the stations of a path, the form error along a path against separate runs of
// the model at each station, the feed that holds, a patch's plan, and check's findings.
#include "core/io/project_file.h"
#include "core/io/project_json.h"
#include "core/milling/ball_end_geometry.h"
#include "core/milling/milled_features.h"
#include "core/project/project_validation.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The tool of 001 (Ø12 mm, two flutes, 30° helix) in its holder (001 §4: k = 6306 N/mm,
// k_θ = 1.656·10⁷ N·mm/rad), a Ø9.6 mm carbide cylinder 40 mm out; test coefficients of the order
// of a titanium alloy's.
BallEndTool paperTool()
{
    BallEndTool t;
    t.diameter_mm = 12.0;
    t.flutes = 2;
    t.helix_deg = 30.0;
    t.overhang_mm = 40.0;
    t.equivalentDiameter_mm = 9.6;
    t.youngsModulus_N_mm2 = 630000.0;
    t.holderStiffness_N_mm = 6306.0;
    t.holderRotational_N_mm_rad = 1.656e7;
    return t;
}

MilledFeature flat()
{
    MilledFeature f;
    f.id = QStringLiteral("M1");
    f.kind = MilledFeatureKind::Flat;
    f.zFrom_mm = 10.0;
    f.zTo_mm = 40.0;
    f.tool = paperTool();
    MillingConditions c;
    c.cut = BallEndCutKind::StepOver;
    c.axialDepth_mm = 0.5;
    c.radialDepth_mm = 1.0;
    c.feedPerTooth_mm = 0.05;
    c.spindle_rpm = 3000.0;
    c.lead_deg = 10.0;
    c.tilt_deg = -5.0;
    f.conditions = c;
    f.coefficients = MillingForceCoefficients{2000.0, 700.0, 400.0, 25.0, 40.0, 8.0};
    f.coefficientsSource = QStringLiteral("test values");
    f.tolerance = MilledTolerance{MilledToleranceType::Flatness, 20.0, {}};
    return f;
}

ClPoint clPoint(double x, double leadAxis_deg)
{
    // Feed along +x on the plane z = 0 (normal +z): the axis leans by the lead towards the feed.
    return {{x, 0.0, 0.0}, {std::sin(leadAxis_deg * kDegree), 0.0, std::cos(leadAxis_deg * kDegree)}, {0.0, 0.0, 1.0}};
}

MilledFeature patch()
{
    MilledFeature f = flat();
    f.id = QStringLiteral("M2");
    f.kind = MilledFeatureKind::Patch;
    f.path = {clPoint(0.0, 5.0), clPoint(3.0, 5.0), clPoint(7.0, 20.0)};
    return f;
}

struct Range {
    double least = 0.0;
    double greatest = 0.0;
};

// δ_N's range over a revolution from the model run on its own at one lead and tilt.
Range normalRange(const MilledFeature &f, double lead_rad, double tilt_rad, double feed_mm)
{
    QStringList missing;
    const MilledFeatureInputs in = *milledFeatureInputs(f, missing);
    BallEndCut cut = in.cut;
    cut.lead_rad = lead_rad;
    cut.tilt_rad = tilt_rad;
    cut.feedPerTooth_mm = feed_mm;
    const BallEndDeflection d = ballEndDeflection(in.mill, in.structure, in.coefficients, cut, {});
    return {d.leastSurfaceNormal_mm, d.greatestSurfaceNormal_mm};
}

Project projectWith(const MilledFeature &f)
{
    const auto parsed =
        readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn"));
    Project p = *parsed.project;
    p.milledFeatures = {f};
    return p;
}

bool hasFinding(const Diagnostics &findings, const QString &field, const QString &text, Severity severity)
{
    for (const Diagnostic &d : findings) {
        if (d.field == field && d.message.contains(text) && d.severity == severity)
            return true;
    }
    return false;
}

QString listed(const Diagnostics &findings)
{
    QStringList lines;
    for (const Diagnostic &d : findings)
        lines << d.field + QStringLiteral(": ") + d.message;
    return lines.join(QLatin1Char('\n'));
}

} // namespace

class TestMilledFeatures : public QObject {
    Q_OBJECT

private Q_SLOTS:

    // The axis T·(0, 0, 1) of eq. 6 at a lead and tilt gives them back; by hand, feed along +x on a
    // plane with normal +z: the axis (sin 10°, 0, cos 10°) leans 10° towards the feed (lead 10°,
    // tilt 0), and (0, −sin 5°, cos 5°) leans 5° against C = N × F = +y (tilt 5°). A normal and feed
    // turned together with the axis change nothing.
    void leadAndTiltOfAnAxis()
    {
        const LeadTilt lead = leadTiltOfAxis({std::sin(10 * kDegree), 0, std::cos(10 * kDegree)}, {0, 0, 1}, {1, 0, 0});
        QVERIFY(std::abs(lead.lead_rad - 10 * kDegree) < 1e-12 && std::abs(lead.tilt_rad) < 1e-12);
        const LeadTilt tilt = leadTiltOfAxis({0, -std::sin(5 * kDegree), std::cos(5 * kDegree)}, {0, 0, 1}, {1, 0, 0});
        QVERIFY(std::abs(tilt.lead_rad) < 1e-12 && std::abs(tilt.tilt_rad - 5 * kDegree) < 1e-12);
        for (const auto &[leadDeg, tiltDeg] : {std::pair{25.0, -15.0}, std::pair{-40.0, 30.0}}) {
            const Eigen::Vector3d a = leadTiltTransform(leadDeg * kDegree, tiltDeg * kDegree).col(2);
            const LeadTilt back = leadTiltOfAxis({a.x(), a.y(), a.z()}, {0, 0, 1}, {1, 0, 0});
            QVERIFY(std::abs(back.lead_rad - leadDeg * kDegree) < 1e-12);
            QVERIFY(std::abs(back.tilt_rad - tiltDeg * kDegree) < 1e-12);
            // The same, the frame turned 90° about x: normal −y... feed +x, normal +y, C = y × x = −z.
            const LeadTilt turned = leadTiltOfAxis({a.x(), -a.y(), a.z()}, {0, 0, 1}, {1, 0, 0});
            QVERIFY(std::abs(turned.tilt_rad + tiltDeg * kDegree) < 1e-12);
            const LeadTilt rotated = leadTiltOfAxis({a.x(), -a.z(), a.y()}, {0, -1, 0}, {1, 0, 0});
            QVERIFY(std::abs(rotated.lead_rad - leadDeg * kDegree) < 1e-12);
            QVERIFY(std::abs(rotated.tilt_rad - tiltDeg * kDegree) < 1e-12);
        }
    }

    // Arc lengths 0, 3, 7 mm; the feed of the last point is the step before it; a feed with a part
    // along the normal (a ramp) counts only along the surface.
    void stationsOfAPath()
    {
        const std::vector<PathStation> s = pathStations(patch().path, 0.0);
        QCOMPARE(s.size(), std::size_t{3});
        QCOMPARE(s[1].arcLength_mm, 3.0);
        QCOMPARE(s[2].arcLength_mm, 7.0);
        QVERIFY(std::abs(s[2].angles.lead_rad - 20 * kDegree) < 1e-12);
        std::vector<ClPoint> ramp = patch().path;
        ramp[1].position_mm = {3.0, 0.0, 4.0};
        const std::vector<PathStation> r = pathStations(ramp, 0.0);
        QCOMPARE(r[1].arcLength_mm, 5.0);
        QVERIFY(std::abs(r[0].angles.lead_rad - 5 * kDegree) < 1e-12);
        // A path that turns from +x to +y at its second point: there the feed is the step to come,
        // +y, with C = N × F = −x, so the axis leaning 5° along +x is a tilt of 5° and no lead; at
        // the last point, the step that came.
        std::vector<ClPoint> turning = patch().path;
        turning[2].position_mm = {3.0, 4.0, 0.0};
        const std::vector<PathStation> t = pathStations(turning, 0.0);
        QVERIFY(std::abs(t[1].angles.lead_rad) < 1e-12 && std::abs(t[1].angles.tilt_rad - 5 * kDegree) < 1e-12);
        QVERIFY(std::abs(t[2].angles.lead_rad) < 1e-12 && std::abs(t[2].angles.tilt_rad - 20 * kDegree) < 1e-12);
        QCOMPARE(t[2].arcLength_mm, 7.0);
        // The ball's centre, tip + R·axis, moves with the contact: with R = 6 mm the last step, from an
        // axis 5° to one 20° from the normal, runs from (3 + 6 sin 5°, 6 cos 5°) to (7 + 6 sin 20°,
        // 6 cos 20°) in x and z.
        const std::vector<PathStation> ball = pathStations(patch().path, 6.0);
        const double dx = 7.0 + 6.0 * std::sin(20 * kDegree) - 3.0 - 6.0 * std::sin(5 * kDegree);
        const double dz = 6.0 * std::cos(20 * kDegree) - 6.0 * std::cos(5 * kDegree);
        QVERIFY(std::abs(ball[2].arcLength_mm - (3.0 + std::hypot(dx, dz))) < 1e-12);
        std::vector<ClPoint> bad = patch().path;
        bad[1].toolAxis = {0.0, 0.0, -1.0};
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)pathStations(bad, 0.0));
        bad = patch().path;
        bad[2].position_mm = bad[1].position_mm;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)pathStations(bad, 0.0));
    }

    // A flat is one cut: its form error is the spread of δ_N over a revolution of the model run on
    // its own at the feature's lead; a patch's is the spread over all its stations together, from
    // the runs at 5° and 20°; with datums the profile is located: 2 max |δ_N|.
    void formErrorAlongThePath()
    {
        const MilledFeatureEvaluation f = evaluateMilledFeature(flat());
        QVERIFY2(f.evaluated(), qPrintable(f.missing.join(QLatin1Char(',')) + f.refusal));
        const Range one = normalRange(flat(), 10 * kDegree, -5 * kDegree, 0.05);
        QVERIFY(std::abs(f.formError_mm - (one.greatest - one.least)) < 1e-12);
        QCOMPARE(f.path.size(), std::size_t{2});
        QCOMPARE(f.path.back().station.arcLength_mm, 30.0);

        const MilledFeatureEvaluation p = evaluateMilledFeature(patch());
        const Range at5 = normalRange(patch(), 5 * kDegree, 0.0, 0.05);
        const Range at20 = normalRange(patch(), 20 * kDegree, 0.0, 0.05);
        const double spread = std::max(at5.greatest, at20.greatest) - std::min(at5.least, at20.least);
        QVERIFY2(std::abs(p.formError_mm - spread) < 1e-12,
                 qPrintable(QStringLiteral("%1 %2").arg(p.formError_mm).arg(spread)));
        QCOMPARE(p.path.size(), std::size_t{3});
        QCOMPARE(p.path[2].greatestNormal_mm, at20.greatest);
        QCOMPARE(p.passes, spread <= 0.020);

        MilledFeature located = patch();
        located.tolerance = MilledTolerance{MilledToleranceType::Profile, 20.0, {QStringLiteral("A")}};
        const double largest =
            std::max({std::abs(at5.least), std::abs(at5.greatest), std::abs(at20.least), std::abs(at20.greatest)});
        QVERIFY(std::abs(evaluateMilledFeature(located).formError_mm - 2.0 * largest) < 1e-12);
    }

    // A tolerance between the error of the edge forces alone (a feed near 0) and that at the planned
    // feed: the feed that holds is below the planned one, and at it the path's error is the
    // tolerance (the model run again there); a loose one holds at the planned feed.
    void feedThatHolds()
    {
        MilledFeature f = patch();
        const double planned = evaluateMilledFeature(f).formError_mm;
        f.conditions->feedPerTooth_mm = 1e-9;
        const double edgeOnly = evaluateMilledFeature(f).formError_mm;
        QVERIFY2(edgeOnly < planned, qPrintable(QStringLiteral("%1 %2").arg(edgeOnly).arg(planned)));
        const double tolerance = 0.5 * (edgeOnly + planned);
        f.conditions->feedPerTooth_mm = 0.05;
        f.tolerance->zone_um = tolerance * 1000.0;
        const MilledFeatureEvaluation tight = evaluateMilledFeature(f);
        QVERIFY(!tight.passes);
        QVERIFY(tight.margin_mm < 0.0);
        const double feed = tight.holdingFeedPerTooth_mm;
        QVERIFY2(feed > 0.0 && feed < 0.05, qPrintable(QString::number(feed)));
        f.conditions->feedPerTooth_mm = feed;
        QVERIFY(std::abs(evaluateMilledFeature(f).formError_mm - tolerance) < 1e-9);
        f.tolerance->zone_um = 2.0 * planned * 1000.0;
        f.conditions->feedPerTooth_mm = 0.05;
        QCOMPARE(evaluateMilledFeature(f).holdingFeedPerTooth_mm, 0.05);
    }

    // A patch's plan is the largest feed up to the highest at which the whole path holds; a flat's
    // plans lead and tilt too (within the bounds, and holding the tolerance run again there).
    void planOfAPatch()
    {
        MilledFeature f = patch();
        f.tolerance->zone_um = 10.0;
        BallEndPlanSettings settings;
        settings.highestFeedPerTooth_mm = 0.3;
        const MilledFeaturePlan plan = planMilledFeature(f, settings);
        QVERIFY(!plan.leadTiltPlanned);
        QVERIFY(plan.plan.feasible);
        const double feed = plan.plan.cut.feedPerTooth_mm;
        f.conditions->feedPerTooth_mm = feed;
        const double at = evaluateMilledFeature(f).formError_mm;
        f.conditions->feedPerTooth_mm = feed * 1.02;
        const double above = evaluateMilledFeature(f).formError_mm;
        QVERIFY2(at <= 0.010 + 1e-9 && (feed == 0.3 || above > 0.010),
                 qPrintable(QStringLiteral("%1 at %2, %3 above").arg(at).arg(feed).arg(above)));
        QCOMPARE(plan.plan.feedRate_mm_min, feed * 2 * 3000.0);

        MilledFeature flatOne = flat();
        flatOne.tolerance->zone_um = 10.0;
        settings.leadLowest_rad = settings.tiltLowest_rad = 5 * kDegree;
        settings.leadHighest_rad = settings.tiltHighest_rad = 30 * kDegree;
        settings.columns = settings.rows = 5;
        settings.windowResolution = {60, 120};
        const MilledFeaturePlan flatPlan = planMilledFeature(flatOne, settings);
        QVERIFY(flatPlan.leadTiltPlanned && flatPlan.plan.feasible);
        const BallEndCut &cut = flatPlan.plan.cut;
        QVERIFY(cut.lead_rad >= 5 * kDegree - 1e-12 && cut.lead_rad <= 30 * kDegree + 1e-12);
        flatOne.conditions->lead_deg = cut.lead_rad / kDegree;
        flatOne.conditions->tilt_deg = cut.tilt_rad / kDegree;
        flatOne.conditions->feedPerTooth_mm = cut.feedPerTooth_mm;
        QVERIFY(evaluateMilledFeature(flatOne).formError_mm <= 0.010 + 1e-9);
    }

    // What is not given is named, nothing is computed; what the model refuses is said.
    void missingAndRefused()
    {
        MilledFeature f = flat();
        f.coefficients.reset();
        f.tool->holderStiffness_N_mm.reset();
        const MilledFeatureEvaluation e = evaluateMilledFeature(f);
        QVERIFY(!e.evaluated());
        QCOMPARE(e.missing.size(), 2);
        QVERIFY(e.missing.join(QLatin1Char(' ')).contains(QStringLiteral("coefficients")));
        QVERIFY(e.path.empty());
        MilledFeature deep = flat();
        deep.conditions->axialDepth_mm = 8.0; // deeper than the Ø12 mm ball's 6 mm
        const MilledFeatureEvaluation refused = evaluateMilledFeature(deep);
        QVERIFY(refused.refusal.contains(QStringLiteral("axial depth")));
        MilledFeature noModulus = flat();
        noModulus.tool->youngsModulus_N_mm2.reset();
        QVERIFY(evaluateMilledFeature(noModulus).carbideAssumed);
        // A shank of 1e-300 mm bends without bound: the deflection is not finite, and a flat whose
        // NaN stations were passed over was said to pass with a form error of 0.
        MilledFeature thread = flat();
        thread.tool->equivalentDiameter_mm = 1e-300;
        const MilledFeatureEvaluation notFinite = evaluateMilledFeature(thread);
        QVERIFY(!notFinite.evaluated());
        QVERIFY(!notFinite.passes);
        QVERIFY2(notFinite.refusal.contains(QStringLiteral("not finite")), qPrintable(notFinite.refusal));
    }

    // check: an unknown datum, a flatness with datums, a path axis into the surface, a shared id are
    // errors naming the field; a feature without coefficients is a warning naming them.
    void checkNamesTheField()
    {
        MilledFeature f = patch();
        f.tolerance = MilledTolerance{MilledToleranceType::Flatness, 20.0, {QStringLiteral("Q")}};
        f.path[1].toolAxis = {0.0, 0.0, -1.0};
        f.coefficients.reset();
        Project p = projectWith(f);
        p.milledFeatures.push_back(flat());
        p.milledFeatures.back().id = f.id;
        const Diagnostics findings = validateProject(p);
        const QString all = listed(findings);
        QVERIFY2(hasFinding(findings, QStringLiteral("milled_features[0].tolerance.datums[0]"), QStringLiteral("'Q'"),
                            Severity::Error),
                 qPrintable(all));
        QVERIFY2(hasFinding(findings, QStringLiteral("milled_features[0].tolerance.datums"),
                            QStringLiteral("flatness has no datums"), Severity::Error),
                 qPrintable(all));
        QVERIFY2(hasFinding(findings, QStringLiteral("milled_features[0].path"), QStringLiteral("path point 2"),
                            Severity::Error),
                 qPrintable(all));
        QVERIFY2(hasFinding(findings, QStringLiteral("milled_features[1].id"), QStringLiteral("'M2'"), Severity::Error),
                 qPrintable(all));
        QVERIFY2(hasFinding(findings, QStringLiteral("milled_features[0]"), QStringLiteral("cutting coefficients"),
                            Severity::Warning),
                 qPrintable(all));
        QVERIFY2(!hasErrors(validateProject(projectWith(flat()))),
                 qPrintable(listed(validateProject(projectWith(flat())))));
    }

    // Every field survives the file (up milling, a located profile, a slot's radial depth, a tool
    // without springs or modulus, coefficients without a source); a bad keyword names its field and
    // value.
    void roundTripThroughJson()
    {
        MilledFeature f = patch();
        f.description = QStringLiteral("STEP faces 4, 5");
        f.tool->youngsModulus_N_mm2.reset();
        MilledFeature slot = flat();
        slot.id = QStringLiteral("M3");
        slot.conditions->cut = BallEndCutKind::Slot;
        slot.conditions->direction = MillingDirection::Up;
        slot.conditions->radialDepth_mm = 0.7;
        slot.tool->holderStiffness_N_mm.reset();
        slot.tool->holderRotational_N_mm_rad.reset();
        slot.coefficientsSource.clear();
        slot.tolerance = MilledTolerance{MilledToleranceType::Profile, 12.5, {QStringLiteral("A")}};
        Project p = projectWith(f);
        p.milledFeatures.push_back(slot);
        const ProjectParseResult back = parseProjectJson(serializeProjectJson(p));
        QVERIFY(back.project.has_value());
        QVERIFY(back.project->milledFeatures == p.milledFeatures);
        QByteArray json = serializeProjectJson(p);
        json.replace("\"step_over\"", "\"pocket\"");
        const ProjectParseResult bad = parseProjectJson(json);
        QVERIFY2(hasFinding(bad.diagnostics, QStringLiteral("milled_features[0].conditions.cut"),
                            QStringLiteral("pocket"), Severity::Error),
                 qPrintable(listed(bad.diagnostics)));
    }
};

QTEST_GUILESS_MAIN(TestMilledFeatures)
#include "tst_milled_features.moc"
