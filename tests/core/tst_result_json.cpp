// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON tolturn-cli prints of its results (core/io/result_json.h): units converted as the keys
// say, numbers only where a result has them, the roughing depth shared out, and the ISO 286 limits
// of a class against the standard's table.
#include "tests/core/test_support.h"

#include "core/io/result_json.h"

#include <QJsonArray>
#include <QTest>

#include <limits>

using namespace tolturn;

namespace {

// Sums and products of exact decimals, to a rounding error.
bool near(double got, double want)
{
    return test::nearAbsolute(got, want, 1e-9);
}

} // namespace

class TestResultJson : public QObject {
    Q_OBJECT
private Q_SLOTS:

    // One station: mm become µm, the radius error doubles into the diameter error, radians become
    // µrad; the tangential direction has no toolpost or thermal term.
    void deviationInMicrometres()
    {
        Station st;
        st.z_mm = 12.5;
        st.nominalRadius_mm = 20.0;
        st.spindleSpeed_rpm = 1591.5;
        st.radial.spindleChuck_mm = 0.002;
        st.radial.toolpost_mm = 0.001;
        st.radial.workpiece_mm = 0.0045;
        st.radial.thermal_mm = 0.0005;
        st.tangential.workpiece_mm = 0.0002;
        st.radiusError_mm = 0.0081;
        st.sectionRotation_rad = 3.0e-6;
        DeviationResult r;
        r.inputs = TurningInputs{};
        r.inputs->forces = {400.0, 150.0, 120.0};
        r.inputs->forceModel = QStringLiteral("kienzle");
        r.features.push_back({QStringLiteral("O2"), ContourSide::Outer, SegmentKind::Cylinder, {st}});
        r.faces.push_back({QStringLiteral("O3"), ContourSide::Outer, 40.0, 1.0e-4, 0.0015});
        r.maxPower_kW = 3.2;
        Project project;
        project.materialId = QStringLiteral("C45E-N");
        const QJsonObject json = deviationJson(QStringLiteral("part.tolturn"), project, r);
        QCOMPARE(json.value(QStringLiteral("file")).toString(), QStringLiteral("part.tolturn"));
        QCOMPARE(json.value(QStringLiteral("material")).toString(), QStringLiteral("C45E-N"));
        QCOMPARE(json.value(QStringLiteral("forces_N")).toObject().value(QStringLiteral("tangential")).toDouble(),
                 400.0);
        QCOMPARE(json.value(QStringLiteral("max_power_kW")).toDouble(), 3.2);
        const QJsonObject feature = json.value(QStringLiteral("features")).toArray().at(0).toObject();
        QCOMPARE(feature.value(QStringLiteral("id")).toString(), QStringLiteral("O2"));
        QCOMPARE(feature.value(QStringLiteral("side")).toString(), QStringLiteral("outer"));
        const QJsonObject station = feature.value(QStringLiteral("stations")).toArray().at(0).toObject();
        QCOMPARE(station.value(QStringLiteral("nominal_diameter_mm")).toDouble(), 40.0);
        const QJsonObject radial = station.value(QStringLiteral("radial_um")).toObject();
        QVERIFY(near(radial.value(QStringLiteral("total")).toDouble(), 2.0 + 1.0 + 4.5 + 0.5)); // 8 µm
        QVERIFY(near(radial.value(QStringLiteral("spindle_chuck")).toDouble(), 2.0));
        QVERIFY(near(radial.value(QStringLiteral("thermal")).toDouble(), 0.5));
        const QJsonObject tangential = station.value(QStringLiteral("tangential_um")).toObject();
        QVERIFY(!tangential.contains(QStringLiteral("toolpost")) && !tangential.contains(QStringLiteral("thermal")));
        QVERIFY(near(tangential.value(QStringLiteral("total")).toDouble(), 0.2));
        QVERIFY(near(station.value(QStringLiteral("radius_error_um")).toDouble(), 8.1));
        QVERIFY(near(station.value(QStringLiteral("diameter_error_um")).toDouble(), 16.2));
        QVERIFY(near(station.value(QStringLiteral("section_rotation_urad")).toDouble(), 3.0));
        const QJsonObject face = json.value(QStringLiteral("faces")).toArray().at(0).toObject();
        QVERIFY(near(face.value(QStringLiteral("axial_runout_um")).toDouble(), 1.5));
        QVERIFY(!json.contains(QStringLiteral("boring_bar"))); // no boring bar named
    }

    // A verdict's numbers appear only where it has them.
    void verdictNumbersOnlyWhereKnown()
    {
        ToleranceEvaluation e;
        e.toleranceId = QStringLiteral("T1");
        e.type = ToleranceType::Diameter;
        e.featureId = QStringLiteral("O2");
        e.verdict = Verdict::PassesAsProgrammed;
        e.value_um = 12.0;
        e.limit_um = 25.0;
        e.utilisation_pct = 48.0;
        const QJsonObject o = evaluationJson(e);
        QCOMPARE(o.value(QStringLiteral("id")).toString(), QStringLiteral("T1"));
        QCOMPARE(o.value(QStringLiteral("value_um")).toDouble(), 12.0);
        QCOMPARE(o.value(QStringLiteral("utilisation_pct")).toDouble(), 48.0);
        QVERIFY(!o.contains(QStringLiteral("nominal_mm")));
        QVERIFY(!o.contains(QStringLiteral("offset_um")));
    }

    // The stiffness a tolerance needs, in N/µm (the model works in N/mm); a window's upper end; none
    // for a tolerance stiffness cannot bring in.
    void requiredStiffnessInNewtonsPerMicrometre()
    {
        ToleranceRangeEvaluation e;
        e.chuck = RequiredStiffness{RequiredStiffness::Kind::Window, 120000.0, 480000.0};
        e.tailstock = RequiredStiffness{RequiredStiffness::Kind::NotReachable, 0.0, 0.0};
        const QJsonObject o = rangeEvaluationJson(e);
        const QJsonObject chuck = o.value(QStringLiteral("required_chuck_stiffness")).toObject();
        QCOMPARE(chuck.value(QStringLiteral("kind")).toString(), QStringLiteral("window"));
        QCOMPARE(chuck.value(QStringLiteral("N_per_um")).toDouble(), 120.0);
        QCOMPARE(chuck.value(QStringLiteral("fails_again_at_N_per_um")).toDouble(), 480.0);
        const QJsonObject tailstock = o.value(QStringLiteral("required_tailstock_stiffness")).toObject();
        QCOMPARE(tailstock.value(QStringLiteral("kind")).toString(), QStringLiteral("not_reachable"));
        QVERIFY(!tailstock.contains(QStringLiteral("N_per_um")));
        QVERIFY(!o.contains(QStringLiteral("at_stiff_end")));
        QVERIFY(
            rangeEvaluationJson(ToleranceRangeEvaluation{}).value(QStringLiteral("required_chuck_stiffness")).isNull());
    }

    // A constraint's violation in per cent: 2.4 kW against a 2 kW limit is 20 % over.
    void constraintViolationInPerCent()
    {
        ConstraintValue c;
        c.name = QStringLiteral("power");
        c.value = 2.4;
        c.limit = 2.0;
        c.unit = QStringLiteral("kW");
        const QJsonObject o = constraintsJson({c}).at(0).toObject();
        QCOMPARE(o.value(QStringLiteral("name")).toString(), QStringLiteral("power"));
        QVERIFY(near(o.value(QStringLiteral("violation_pct")).toDouble(), 20.0));
    }

    // A tolerance whose deviation overflows (toleranceConstraintsOf) has no number to write: JSON
    // cannot hold infinity, and a null would leave a hole. It is said instead, with its limit.
    void constraintNotFiniteIsSaid()
    {
        ConstraintValue c;
        c.name = QStringLiteral("tolerances");
        c.subject = QStringLiteral("T1");
        c.value = std::numeric_limits<double>::infinity();
        c.limit = 16.0;
        c.unit = QStringLiteral("µm");
        const QJsonObject o = constraintsJson({c}).at(0).toObject();
        QVERIFY(o.value(QStringLiteral("not_finite")).toBool());
        QVERIFY(!o.contains(QStringLiteral("value")));
        QVERIFY(!o.contains(QStringLiteral("violation_pct")));
        QCOMPARE(o.value(QStringLiteral("limit")).toDouble(), 16.0);
        QCOMPARE(c.violatedBy(), QStringLiteral("with a predicted value that is not finite"));
        c.value = 20.0; // 20 µm against 16 µm: 25 % over
        QCOMPARE(c.violatedBy(), QStringLiteral("by 25 %"));
    }

    // ISO 286-2 Table 2 (holes H) and ISO 286-1 Table 1: Ø50 H7 is +25/0 µm, IT7 = 25 µm over 30 to
    // 50 mm; Ø50 g6 is -9/-25 µm (es = -9 µm, IT6 = 16 µm).
    void iso286LimitsAsTheTableGivesThem()
    {
        const iso286::LimitsResult h7 = iso286::limits(50.0, QStringLiteral("H7"));
        QVERIFY(h7.limits);
        const QJsonObject hole = classLimitsJson(*h7.limits);
        QCOMPARE(hole.value(QStringLiteral("class")).toString(), QStringLiteral("H7"));
        QCOMPARE(hole.value(QStringLiteral("upper_um")).toDouble(), 25.0);
        QCOMPARE(hole.value(QStringLiteral("lower_um")).toDouble(), 0.0);
        QCOMPARE(hole.value(QStringLiteral("it_grade")).toString(), QStringLiteral("IT7"));
        QCOMPARE(hole.value(QStringLiteral("it_um")).toDouble(), 25.0);
        const iso286::LimitsResult g6 = iso286::limits(50.0, QStringLiteral("g6"));
        QVERIFY(g6.limits);
        const QJsonObject shaft = classLimitsJson(*g6.limits);
        QCOMPARE(shaft.value(QStringLiteral("upper_um")).toDouble(), -9.0);
        QCOMPARE(shaft.value(QStringLiteral("lower_um")).toDouble(), -25.0);
        QCOMPARE(shaft.value(QStringLiteral("nominal_mm")).toDouble(), 50.0);
    }
};

QTEST_GUILESS_MAIN(TestResultJson)
#include "tst_result_json.moc"
