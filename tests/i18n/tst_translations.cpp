// SPDX-License-Identifier: GPL-3.0-or-later
// The German and Spanish translations are complete: every string the sources mark for
// translation (as lupdate finds it now) has a finished translation with the same placeholders,
// and the compiled translations are what the program shows.
#include "core/project/keywords.h"
#include "core/tolerance/iso286.h"
#include "translations/i18n.h"

#include <QCoreApplication>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <map>

using namespace tolturn;

namespace {

struct Message {
    QString source;
    QStringList translations; // one, or one per plural form
    QString type;             // "", "unfinished", "vanished", "obsolete"
};

// (context, source) → message, read from a Qt Linguist file.
using Catalogue = std::map<std::pair<QString, QString>, Message>;

void readMessage(QXmlStreamReader &xml, const QString &context, Catalogue &out)
{
    Message m;
    while (xml.readNextStartElement()) {
        if (xml.name() == QLatin1String("source")) {
            m.source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
            m.type = xml.attributes().value(QLatin1String("type")).toString();
            // Plural messages hold their forms as <numerusform> children.
            QString text;
            while (!xml.isEndElement() || xml.name() != QLatin1String("translation")) {
                xml.readNext();
                if (xml.isCharacters())
                    text += xml.text();
                else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                    m.translations << xml.readElementText();
            }
            if (m.translations.isEmpty())
                m.translations << text;
        } else {
            xml.skipCurrentElement();
        }
    }
    out[{context, m.source}] = m;
}

Catalogue readCatalogue(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    QXmlStreamReader xml(&file);
    Catalogue out;
    QString context;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement() && xml.name() == QLatin1String("name"))
            context = xml.readElementText();
        else if (xml.isStartElement() && xml.name() == QLatin1String("message"))
            readMessage(xml, context, out);
    }
    if (xml.hasError())
        qFatal("%s: %s", qPrintable(path), qPrintable(xml.errorString()));
    return out;
}

QString tsPath(const QString &language)
{
    return QStringLiteral(TOLTURN_SOURCE_DIR "/translations/tolturn_%1.ts").arg(language);
}

// The arguments a text is filled with: %1 … %99 and %n, each once, sorted.
QStringList placeholders(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral("%(\\d{1,2}|n)"));
    QSet<QString> found;
    for (auto it = pattern.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured());
    QStringList list(found.begin(), found.end());
    list.sort();
    return list;
}

// A menu or button accelerator: '&' before a letter ("&File"), not "&&" nor "Li & Du".
bool hasAccelerator(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral("(^|[^&])&[^&\\s]"));
    return pattern.match(text).hasMatch();
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT

private Q_SLOTS:

    void languages_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("German") << QStringLiteral("de");
        QTest::newRow("Spanish") << QStringLiteral("es");
    }

    // Each message finished, non-empty, with the source's placeholders and accelerator.
    void everyMessageFinished_data() { languages_data(); }

    void everyMessageFinished()
    {
        QFETCH(QString, language);
        const Catalogue catalogue = readCatalogue(tsPath(language));
        QVERIFY(catalogue.size() > 700); // the catalogue was read, not an empty file
        for (const auto &[key, m] : catalogue) {
            const QString where = key.first + QStringLiteral(" / \"") + m.source + QLatin1Char('"');
            QVERIFY2(m.type.isEmpty(), qPrintable(where + QStringLiteral(" is ") + m.type));
            for (const QString &t : m.translations) {
                QVERIFY2(!t.trimmed().isEmpty(), qPrintable(where + QStringLiteral(" has an empty translation")));
                QVERIFY2(placeholders(t) == placeholders(m.source),
                         qPrintable(where + QStringLiteral(": placeholders differ in \"") + t + QLatin1Char('"')));
                QVERIFY2(hasAccelerator(t) == hasAccelerator(m.source),
                         qPrintable(where + QStringLiteral(": accelerator differs in \"") + t + QLatin1Char('"')));
            }
        }
    }

    // English, the source language, has only its plural forms (lupdate -pluralonly): every one
    // finished, singular and plural different, and each found again in today's sources.
    void englishPluralsFinished()
    {
        const Catalogue catalogue = readCatalogue(tsPath(QStringLiteral("en")));
        QVERIFY(catalogue.size() >= 7);
        for (const auto &[key, m] : catalogue) {
            const QString where = key.first + QStringLiteral(" / \"") + m.source + QLatin1Char('"');
            QVERIFY2(m.type.isEmpty(), qPrintable(where + QStringLiteral(" is ") + m.type));
            QVERIFY2(m.translations.size() == 2 && m.translations[0] != m.translations[1],
                     qPrintable(where + QStringLiteral(": needs a singular and a plural")));
            QVERIFY2(!m.translations[1].contains(QStringLiteral("(s)")), qPrintable(where));
        }
        QTemporaryDir dir;
        const QString scanned = dir.filePath(QStringLiteral("plurals.ts"));
        QProcess lupdate;
        lupdate.start(QStringLiteral(TOLTURN_LUPDATE),
                      {QStringLiteral("-silent"), QStringLiteral("-pluralonly"), QStringLiteral("-locations"),
                       QStringLiteral("none"), QStringLiteral("-I"), QStringLiteral(TOLTURN_SOURCE_DIR),
                       QStringLiteral("@" TOLTURN_TRANSLATED_SOURCES), QStringLiteral("-ts"), scanned});
        QVERIFY(lupdate.waitForFinished(120000));
        QCOMPARE(lupdate.exitCode(), 0);
        for (const auto &[key, m] : readCatalogue(scanned)) {
            const auto it = catalogue.find(key);
            QVERIFY2(it != catalogue.end() && it->second.type.isEmpty(),
                     qPrintable(QStringLiteral("no English plural forms for ") + m.source +
                                QStringLiteral(" (run update_translations and fill tolturn_en.ts)")));
        }
    }

    // In English the plural forms are used: "1 pass", "2 passes", never "pass(es)".
    void englishPluralsAreLoaded()
    {
        installTranslations(*QCoreApplication::instance(), QLocale(QLocale::English));
        QCOMPARE(QCoreApplication::translate("CommandLine", "%n pass(es)", nullptr, 1), QStringLiteral("1 pass"));
        QCOMPARE(QCoreApplication::translate("CommandLine", "%n pass(es)", nullptr, 9), QStringLiteral("9 passes"));
    }

    // lupdate run over today's sources finds no string the committed files lack: a string added
    // to the code without its translations fails here.
    void sourcesFullyTranslated_data() { languages_data(); }

    void sourcesFullyTranslated()
    {
        QFETCH(QString, language);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString scanned = dir.filePath(QStringLiteral("scanned.ts"));
        QProcess lupdate;
        lupdate.start(QStringLiteral(TOLTURN_LUPDATE),
                      {QStringLiteral("-silent"), QStringLiteral("-locations"), QStringLiteral("none"),
                       QStringLiteral("-I"), QStringLiteral(TOLTURN_SOURCE_DIR),
                       QStringLiteral("@" TOLTURN_TRANSLATED_SOURCES), QStringLiteral("-ts"), scanned});
        QVERIFY(lupdate.waitForFinished(120000));
        QCOMPARE(lupdate.exitCode(), 0);
        const Catalogue found = readCatalogue(scanned);
        QVERIFY(found.size() > 700);
        const Catalogue committed = readCatalogue(tsPath(language));
        QStringList missing;
        for (const auto &[key, m] : found) {
            const auto it = committed.find(key);
            if (it == committed.end() || !it->second.type.isEmpty())
                missing << key.first + QStringLiteral(" / \"") + m.source + QLatin1Char('"');
        }
        QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("untranslated in tolturn_%1.ts (run the "
                                                              "update_translations target and translate):\n")
                                                   .arg(language) +
                                               missing.join(QLatin1Char('\n'))));
    }

    // The compiled translations are built in and found under the context the code asks for:
    // a Qt class (MainWindow), and core strings behind Q_DECLARE_TR_FUNCTIONS.
    void translationsAreLoaded_data() { languages_data(); }

    void translationsAreLoaded()
    {
        QFETCH(QString, language);
        installTranslations(*QCoreApplication::instance(), QLocale(language));
        const Catalogue committed = readCatalogue(tsPath(language));
        const auto expected = [&](const char *context, const char *source) {
            return committed.at({QString::fromLatin1(context), QString::fromUtf8(source)}).translations.constFirst();
        };
        QCOMPARE(QCoreApplication::translate("tolturn::MainWindow", "&File"), expected("tolturn::MainWindow", "&File"));
        QCOMPARE(displayName(ClampingMethod::BetweenCentres), expected("Names", "between centres"));
        QCOMPARE(iso286::fitTypeName(iso286::FitType::Clearance), expected("Iso286", "clearance"));
        QVERIFY(displayName(ClampingMethod::BetweenCentres) != QStringLiteral("between centres"));
        // Keywords written to files stay English whatever the language.
        QCOMPARE(iso286::fitTypeKeyword(iso286::FitType::Clearance), QStringLiteral("clearance"));
        QCOMPARE(keyword(ClampingMethod::BetweenCentres), QStringLiteral("centres"));
    }

    // Qt's own texts (the standard buttons of every dialog: Save, Cancel, Yes) come in the same
    // language as TolTurn's, from Qt's catalogue (Debian's qt6-translations-l10n): a German window
    // does not ask "Speichern?" above an English "Cancel".
    void qtStandardButtonsTranslated_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("cancel");
        QTest::addColumn<QString>("save");
        QTest::addColumn<QString>("yes");
        QTest::newRow("German") << QStringLiteral("de") << QStringLiteral("Abbrechen") << QStringLiteral("Speichern")
                                << QStringLiteral("&Ja");
        QTest::newRow("Spanish") << QStringLiteral("es") << QStringLiteral("Cancelar") << QStringLiteral("Guardar")
                                 << QString::fromUtf8("&Sí");
    }

    void qtStandardButtonsTranslated()
    {
        QFETCH(QString, language);
        QFETCH(QString, cancel);
        QFETCH(QString, save);
        QFETCH(QString, yes);
        installTranslations(*QCoreApplication::instance(), QLocale(language));
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), cancel);
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Save"), save);
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "&Yes"), yes);
    }
};

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
