// SPDX-License-Identifier: GPL-3.0-or-later
// Edit > Preferences: display units (mm/µm or in/µin) and the language, stored in the settings;
// the units change every view at once and never the document.
#include "tests/examples.h"

#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "app/gui/settings_dialog.h"
#include "widgets/common/display_units.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/document/project_document.h"
#include "widgets/plot/line_plot.h"
#include "widgets/profile/dimension_item.h"
#include "widgets/profile/feature_panel.h"
#include "widgets/profile/profile_scene.h"
#include "widgets/profile/profile_view.h"
#include "widgets/results/deflection_panel.h"
#include "widgets/setup/setup_panel.h"
#include "widgets/tolerances/tolerance_panel.h"
#include "widgets/tolerances/tolerance_verdict_model.h"

#include <QAbstractItemModelTester>
#include <QComboBox>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>

using namespace tolturn;

namespace {

using tolturn::test::example;

QStringList dimensionTexts(const MainWindow &w)
{
    QStringList texts;
    const QList<QGraphicsItem *> all = w.profileView()->scene()->items();
    for (QGraphicsItem *item : all) {
        if (item->data(kItemKindData).toString() == profile_item::kDimension)
            texts << static_cast<DimensionItem *>(item)->text();
    }
    return texts;
}

Preferences inches()
{
    Preferences p;
    p.lengthUnit = LengthUnit::Inch;
    return p;
}

} // namespace

class TestSettings : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("TolTurnTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_settings"));
        QSettings().clear();
    }

    void cleanup() { DisplaySettings::instance().setUnits(DisplayUnits()); }

    // Hand conversions with 1 in = 25.4 mm exactly.
    void convertsLengthsAndDeviations()
    {
        const DisplayUnits mm;
        const DisplayUnits in(LengthUnit::Inch);
        QCOMPARE(mm.lengthText(50.0), QStringLiteral("50"));
        QCOMPARE(mm.lengthText(12.3456), QStringLiteral("12.346"));
        QCOMPARE(in.lengthText(50.8), QStringLiteral("2"));      // 50.8 / 25.4
        QCOMPARE(in.lengthText(50.0), QStringLiteral("1.9685")); // 1.968503… in
        QCOMPARE(in.lengthToMm(0.5), 12.7);
        QCOMPARE(in.deviationFromUm(25.4), 1000.0);              // 25.4 µm = 0.001 in
        QCOMPARE(in.deviationText(10.0), QStringLiteral("394")); // 393.70… µin
        QCOMPARE(mm.deviationText(12.34), QStringLiteral("12.3"));
        QCOMPARE(in.lengthSymbol(), QStringLiteral("in"));
        QCOMPARE(in.deviationSymbol(), QString::fromUtf8("µin"));
        QCOMPARE(lengthUnitFromKeyword(keyword(LengthUnit::Inch)), LengthUnit::Inch);
        QCOMPARE(lengthUnitFromKeyword(QStringLiteral("furlong")), LengthUnit::Millimetre);
    }

    // A length is kept exactly while the box shows it, even where the shown number is rounded on
    // a tie (1/16 in = 1.5875 mm shows as 1.587 or 1.588 mm); a typed number is taken as typed.
    void lengthBoxKeepsTheExactLength()
    {
        LengthSpinBox box(1000.0);
        for (const double length : {1.5875, 14.2875, 1.0005, 38.1}) {
            box.setMillimetres(length);
            QCOMPARE(box.millimetres(), length);
            DisplaySettings::instance().setUnits(DisplayUnits(LengthUnit::Inch));
            QCOMPARE(box.millimetres(), length);
            DisplaySettings::instance().setUnits(DisplayUnits());
            QCOMPARE(box.millimetres(), length);
        }
        box.setValue(12.5);
        QCOMPARE(box.millimetres(), 12.5);
        DisplaySettings::instance().setUnits(DisplayUnits(LengthUnit::Inch));
        box.setValue(0.25); // typed in inches
        QCOMPARE(box.millimetres(), 6.35);
        QCOMPARE(box.singleStep(), 0.05);
    }

    void preferencesSurviveARestart()
    {
        Preferences p;
        p.language = QStringLiteral("es");
        p.lengthUnit = LengthUnit::Inch;
        p.planner = QStringLiteral("A. Planner");
        p.currency = QStringLiteral("EUR");
        savePreferences(p);
        QCOMPARE(loadPreferences(), p);
        QCOMPARE(translationLocale(p).language(), QLocale::Spanish);
        QSettings().setValue(QStringLiteral("interface/language"), QStringLiteral("tlh"));
        QVERIFY(loadPreferences().language.isEmpty()); // not a language TolTurn has: the system's
        savePreferences(Preferences());
    }

    // The shop's PostgreSQL database: kept without a password, refused without its host,
    // database and user, and the local file otherwise.
    void measurementStoreIsAPreference()
    {
        Preferences p;
        p.shopDatabase = true;
        p.shopHost = QStringLiteral("db.shop.example");
        p.shopPort = 5433;
        p.shopDatabaseName = QStringLiteral("tolturn");
        p.shopUser = QStringLiteral("planner");
        savePreferences(p);
        QCOMPARE(loadPreferences(), p);
        const StoreLocation shop = measurementStoreLocation(loadPreferences());
        QCOMPARE(shop.kind, StoreLocation::Kind::PostgreSQL);
        QCOMPARE(shop.describe(), QStringLiteral("postgresql://planner@db.shop.example:5433/tolturn"));
        QVERIFY(shop.password.isEmpty());
        QCOMPARE(measurementStoreLocation(Preferences()).describe(), defaultStoreLocation().describe());

        SettingsDialog dialog(p);
        QVERIFY(dialog.shopDatabaseButton()->isChecked());
        QCOMPARE(dialog.shopPortBox()->value(), 5433);
        dialog.shopDatabaseEdit()->clear();
        dialog.shopUserEdit()->clear();
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
        QVERIFY2(dialog.connectionResult()->text().contains(QStringLiteral("database, user")),
                 qPrintable(dialog.connectionResult()->text()));
        dialog.shopDatabaseEdit()->setText(QStringLiteral("tolturn"));
        dialog.shopUserEdit()->setText(QStringLiteral("planner"));
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(dialog.preferences(), p);
        savePreferences(Preferences());
    }

    void dialogShowsAndReturnsTheChoice()
    {
        Preferences current;
        current.language = QStringLiteral("de");
        SettingsDialog dialog(current);
        QCOMPARE(dialog.languageBox()->currentData().toString(), QStringLiteral("de"));
        QCOMPARE(dialog.languageBox()->count(), 4); // system, English, German, Spanish
        QCOMPARE(dialog.unitBox()->currentData().toInt(), static_cast<int>(LengthUnit::Millimetre));
        dialog.unitBox()->setCurrentIndex(dialog.unitBox()->findData(static_cast<int>(LengthUnit::Inch)));
        dialog.languageBox()->setCurrentIndex(0);
        QCOMPARE(dialog.preferences().lengthUnit, LengthUnit::Inch);
        QVERIFY(dialog.preferences().language.isEmpty());
    }

    // Inches: the drawing, the panels, the plots and the verdict table change at once; the
    // project does not (still in mm, not modified).
    void unitsChangeEveryViewButNotTheDocument()
    {
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        const Project before = w.document()->project();
        w.profileView()->selectFeature(QStringLiteral("O4")); // Ø50 h6 from z 35 to 80
        QCOMPARE(w.featurePanel()->startZBox()->value(), 35.0);

        const QAbstractItemModelTester verdictModel(w.tolerancePanel()->model(),
                                                    QAbstractItemModelTester::FailureReportingMode::QtTest);
        w.applyPreferences(inches());
        QVERIFY(dimensionTexts(w).contains(QString::fromUtf8("Ø1.9685 h6"))); // 50 / 25.4
        QVERIFY(dimensionTexts(w).contains(QStringLiteral("5.9055")));        // overall 150 mm
        QCOMPARE(w.featurePanel()->startZBox()->suffix(), QStringLiteral(" in"));
        QVERIFY(std::abs(w.featurePanel()->startZBox()->value() - 35.0 / 25.4) < 1e-5);
        QCOMPARE(w.setupPanel()->clampedLengthBox()->millimetres(), 35.0);
        QVERIFY(w.deflectionPanel()->plot()->csvText().contains(QStringLiteral("[in]")));
        const QAbstractItemModel *verdicts = w.tolerancePanel()->model();
        QCOMPARE(verdicts->headerData(ToleranceVerdictModel::Limit, Qt::Horizontal).toString(),
                 QString::fromUtf8("Limit [µin]"));
        QCOMPARE(w.document()->project(), before);
        QVERIFY(!w.document()->isModified());

        // A corner typed in inches lands in millimetres: 1.5 in = 38.1 mm.
        w.featurePanel()->startZBox()->setValue(1.5);
        QVERIFY(std::abs(w.document()->project().part.outer.segments[3].from.z_mm - 38.1) < 1e-9);

        w.applyPreferences(Preferences());
        QCOMPARE(w.featurePanel()->startZBox()->suffix(), QStringLiteral(" mm"));
        QVERIFY(std::abs(w.featurePanel()->startZBox()->value() - 38.1) < 1e-9);
        QVERIFY(dimensionTexts(w).contains(QString::fromUtf8("Ø50 h6")));
        QCOMPARE(loadPreferences().lengthUnit, LengthUnit::Millimetre);
    }

    void languageChangeIsAnnounced()
    {
        MainWindow w;
        Preferences german;
        german.language = QStringLiteral("de");
        w.applyPreferences(german);
        QVERIFY(w.statusBar()->currentMessage().contains(QStringLiteral("next started")));
        QCOMPARE(loadPreferences().language, QStringLiteral("de"));
        savePreferences(Preferences());
    }
};

QTEST_MAIN(TestSettings)
#include "tst_settings.moc"
