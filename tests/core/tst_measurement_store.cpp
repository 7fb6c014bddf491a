// SPDX-License-Identifier: GPL-3.0-or-later
// The measurement history (issue 15): the same scenarios on an SQLite file and on a throwaway
// PostgreSQL cluster; the schema migration from its first version; concurrent writers.
#include "tests/core/postgres_cluster.h"

#include "core/measurements/measurement_schema.h"
#include "core/measurements/measurement_store.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlError>
#include <QSqlQuery>
#include <QTest>
#include <QThread>

#include <cmath>
#include <memory>

using namespace tolturn;

namespace {

QByteArray exampleProject()
{
    QFile f(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn"));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read the example");
    return f.readAll();
}

// A part of the stepped shaft (Ø56 from z 0 to 35, Ø50 to 80, cone, Ø40 to 118, …) as measured.
MeasuredPart measuredShaft(const QString &machine = QStringLiteral("haas-st-20"))
{
    MeasuredPart p;
    p.machineId = machine;
    p.measuredAt = QDateTime(QDate(2026, 11, 24), QTime(8, 30), Qt::UTC);
    p.measuredBy = QStringLiteral("A. Planner");
    p.method = QStringLiteral("micrometer");
    p.timeSinceStart_min = 45.0;
    p.ambient_C = 21.5;
    // The project as planned for that machine (a part is learned against its own machine's physics).
    QJsonObject project = QJsonDocument::fromJson(exampleProject()).object();
    project.insert(QStringLiteral("machine"), machine);
    p.projectJson = QJsonDocument(project).toJson();
    p.note = QStringLiteral("first part of the batch");
    p.points = {{QStringLiteral("O4"), 40.0, MeasuredQuantity::Diameter, 50.012},
                {QStringLiteral("O4"), 75.0, MeasuredQuantity::Diameter, 50.018},
                {QStringLiteral("O6"), 100.0, MeasuredQuantity::RadialDeviation, 0.006},
                cmmPoint(QStringLiteral("O6"), 12.003, 16.004, 110.0)};
    return p;
}

bool hasErrorAt(const Diagnostics &d, const QString &field, const QString &text)
{
    return std::any_of(d.begin(), d.end(), [&](const Diagnostic &x) {
        return x.severity == Severity::Error && x.field == field && x.message.contains(text);
    });
}

} // namespace

class TestMeasurementStore : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    std::unique_ptr<test::PostgresCluster> m_postgres;
    int m_files = 0;

    // A new, empty store of the row's kind.
    StoreLocation freshLocation()
    {
        QFETCH_GLOBAL(QString, backend);
        if (backend == QLatin1String("sqlite")) {
            StoreLocation l;
            l.file = m_dir.filePath(QStringLiteral("store-%1/measurements.sqlite").arg(++m_files));
            return l;
        }
        // One cluster; every test starts from an empty database.
        StoreLocation l = m_postgres->location();
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), QStringLiteral("reset"));
        db.setHostName(l.host);
        db.setPort(l.port);
        db.setDatabaseName(l.database);
        db.setUserName(l.user);
        if (db.open()) {
            QSqlQuery q(db);
            q.exec(
                QStringLiteral("DROP TABLE IF EXISTS learned_models, measured_points, measured_parts, tolturn_schema"));
            db.close();
        }
        db = QSqlDatabase();
        QSqlDatabase::removeDatabase(QStringLiteral("reset"));
        return l;
    }

    std::unique_ptr<MeasurementStore> openStore(const StoreLocation &l)
    {
        QString error;
        auto store = MeasurementStore::open(l, &error);
        if (!store)
            qWarning("%s", qPrintable(error));
        return store;
    }

private Q_SLOTS:

    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_postgres = std::make_unique<test::PostgresCluster>();
        QVERIFY2(m_postgres->ok(), qPrintable(m_postgres->error()));
    }

    void cleanupTestCase() { m_postgres.reset(); }

    void initTestCase_data()
    {
        QTest::addColumn<QString>("backend");
        QTest::newRow("sqlite") << QStringLiteral("sqlite");
        QTest::newRow("postgresql") << QStringLiteral("postgresql");
    }

    // A part comes back as it went in, with its snapshot, shop conditions and points in order.
    void storesAndReadsBackAPart()
    {
        auto store = openStore(freshLocation());
        QVERIFY(store);
        QCOMPARE(store->schemaVersion(), kMeasurementSchemaVersion);
        Diagnostics problems;
        const MeasuredPart in = measuredShaft();
        const auto id = store->add(in, problems);
        QVERIFY2(id.has_value(), qPrintable(problems.empty() ? QString() : problems.front().toString()));
        QString error;
        const auto out = store->part(*id, &error);
        QVERIFY2(out.has_value(), qPrintable(error));
        MeasuredPart expected = in;
        expected.id = *id;
        QCOMPARE(*out, expected);
        const auto list = store->list({}, &error);
        QVERIFY(list.has_value());
        QCOMPARE(list->size(), std::size_t{1});
        QCOMPARE(list->front().partName, QStringLiteral("Stepped shaft"));
        QCOMPARE(list->front().pointCount, 4);
        // The CMM point keeps its x and y, and its radius √(12.003² + 16.004²) = √400.200025.
        QCOMPARE(out->points[3].quantity, MeasuredQuantity::CmmPoint);
        QCOMPARE(out->points[3].x_mm, 12.003);
        QVERIFY(std::abs(out->points[3].value_mm - std::sqrt(400.200025)) < 1e-12);
        // Without the shop conditions: absent, not zero.
        MeasuredPart bare = measuredShaft();
        bare.timeSinceStart_min.reset();
        bare.ambient_C.reset();
        const auto bareId = store->add(bare, problems);
        QVERIFY(bareId.has_value());
        QVERIFY(!store->part(*bareId, &error)->ambient_C.has_value());
    }

    // Each wrong value named by its field; nothing stored.
    void refusesPartsThatDoNotFit_data()
    {
        QTest::addColumn<QString>("edit");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("message");
        QTest::newRow("feature") << "feature"
                                 << "points[0].feature"
                                 << "no feature \"O99\"";
        QTest::newRow("z") << "z"
                           << "points[0].z_mm"
                           << "z = 90 mm is not on feature O4 (z from 35 to 80 mm)";
        QTest::newRow("diameter") << "diameter"
                                  << "points[1].value_mm"
                                  << "a diameter of 42 mm does not fit feature O4";
        QTest::newRow("deviation") << "deviation"
                                   << "points[2].value_mm"
                                   << "a radial deviation of 2 mm";
        QTest::newRow("machine") << "machine"
                                 << "machine"
                                 << "not given";
        QTest::newRow("other machine") << "other machine"
                                       << "machine"
                                       << "cut on haas-st-30, but its project is planned for haas-st-20";
        QTest::newRow("ambient") << "ambient"
                                 << "ambient_C"
                                 << "not 80";
        QTest::newRow("snapshot") << "snapshot"
                                  << "project"
                                  << "not a valid project";
        QTest::newRow("cmm") << "cmm"
                             << "points[3].x_mm"
                             << "a CMM point at radius 30 mm is not on feature O6 (R20 to R20 mm)";
        QTest::newRow("no points") << "points"
                                   << "points"
                                   << "no measured point";
    }

    void refusesPartsThatDoNotFit()
    {
        QFETCH(QString, edit);
        QFETCH(QString, field);
        QFETCH(QString, message);
        auto store = openStore(freshLocation());
        QVERIFY(store);
        MeasuredPart p = measuredShaft();
        if (edit == QLatin1String("feature"))
            p.points[0].featureId = QStringLiteral("O99");
        else if (edit == QLatin1String("z"))
            p.points[0].z_mm = 90.0;
        else if (edit == QLatin1String("diameter"))
            p.points[1].value_mm = 42.0;
        else if (edit == QLatin1String("deviation"))
            p.points[2].value_mm = 2.0;
        else if (edit == QLatin1String("machine"))
            p.machineId.clear();
        else if (edit == QLatin1String("ambient"))
            p.ambient_C = 80.0;
        else if (edit == QLatin1String("other machine"))
            p.machineId = QStringLiteral("haas-st-30");
        else if (edit == QLatin1String("cmm"))
            p.points[3] = cmmPoint(QStringLiteral("O6"), 18.0, 24.0, 110.0);
        else if (edit == QLatin1String("snapshot"))
            p.projectJson = "{\"format\": \"tolturn-project\"";
        else
            p.points.clear();
        Diagnostics problems;
        QVERIFY(!store->add(p, problems).has_value());
        QVERIFY2(hasErrorAt(problems, field, message),
                 qPrintable(problems.empty() ? QStringLiteral("none") : problems.front().toString()));
        QString error;
        QCOMPARE(store->count({}, &error).value_or(-1), qint64{0});
    }

    // Newest first; by machine, by text, by page; a removed part takes its points with it.
    void listsFiltersAndRemoves()
    {
        auto store = openStore(freshLocation());
        QVERIFY(store);
        Diagnostics problems;
        std::vector<qint64> ids;
        for (int i = 0; i < 4; ++i) {
            MeasuredPart p = measuredShaft(i % 2 == 0 ? QStringLiteral("haas-st-20") : QStringLiteral("haas-st-30"));
            p.measuredAt = p.measuredAt.addSecs(qint64{3600} * i);
            p.measuredBy = i == 3 ? QStringLiteral("B. Inspector") : QStringLiteral("A. Planner");
            if (i == 1)
                p.measuredBy = QStringLiteral("Ömer Öztürk");
            ids.push_back(store->add(p, problems).value_or(-1));
            QVERIFY(ids.back() > 0);
        }
        QString error;
        PartFilter st20;
        st20.machineId = QStringLiteral("haas-st-20");
        const auto machine = store->list(st20, &error);
        QVERIFY2(machine.has_value(), qPrintable(error));
        QCOMPARE(machine->size(), std::size_t{2});
        QCOMPARE(machine->at(0).id, ids[2]); // newest first
        QCOMPARE(machine->at(1).id, ids[0]);
        PartFilter inspector;
        inspector.text = QStringLiteral("inspector");
        QCOMPARE(store->list(inspector, &error)->size(), std::size_t{1});
        // Any letter's case, on SQLite too (its LOWER folds ASCII only); what is typed is text.
        PartFilter accented;
        accented.text = QStringLiteral("öztürk");
        QCOMPARE(store->list(accented, &error)->size(), std::size_t{1});
        QCOMPARE(store->count(accented, &error).value_or(-1), qint64{1});
        PartFilter wildcard;
        wildcard.text = QStringLiteral("%");
        QCOMPARE(store->list(wildcard, &error)->size(), std::size_t{0});
        PartFilter planners;
        planners.text = QStringLiteral("planner");
        planners.limit = 1;
        planners.offset = 1;
        const auto secondPlanner = store->list(planners, &error);
        QCOMPARE(secondPlanner->size(), std::size_t{1});
        QCOMPARE(secondPlanner->front().id, ids[0]); // planners: parts 2 and 0, newest first
        PartFilter page;
        page.limit = 2;
        page.offset = 1;
        const auto second = store->list(page, &error);
        QCOMPARE(second->size(), std::size_t{2});
        QCOMPARE(second->at(0).id, ids[2]);
        QCOMPARE(store->count(st20, &error).value_or(-1), qint64{2});
        QVERIFY(store->remove(ids[1], &error));
        QVERIFY(!store->part(ids[1], &error).has_value());
        QVERIFY(error.contains(QStringLiteral("no part")));
        QVERIFY(!store->remove(ids[1], &error));
        QCOMPARE(store->count({}, &error).value_or(-1), qint64{3});
        // The removed part's points went with it (the reference's ON DELETE CASCADE).
        QSqlDatabase db = QSqlDatabase::database(QSqlDatabase::connectionNames().constLast());
        QSqlQuery q(db);
        QVERIFY(q.exec(QStringLiteral("SELECT COUNT(*) FROM measured_points")) && q.next());
        QCOMPARE(q.value(0).toInt(), 3 * static_cast<int>(measuredShaft().points.size()));
    }

    // A store of the first schema version, with a part in it, is brought to the current version
    // when opened: the part is kept and gets the checksum of its profile.
    void migratesFromTheFirstVersion()
    {
        const StoreLocation l = freshLocation();
        {
            QFETCH_GLOBAL(QString, backend);
            QSqlDatabase db = QSqlDatabase::addDatabase(backend == QLatin1String("sqlite") ? QStringLiteral("QSQLITE")
                                                                                           : QStringLiteral("QPSQL"),
                                                        QStringLiteral("v1"));
            if (backend == QLatin1String("sqlite")) {
                QVERIFY(QDir().mkpath(QFileInfo(l.file).absolutePath()));
                db.setDatabaseName(l.file);
            } else {
                db.setHostName(l.host);
                db.setPort(l.port);
                db.setDatabaseName(l.database);
                db.setUserName(l.user);
            }
            QVERIFY(db.open());
            QString error;
            QVERIFY2(measurements::migrateSchema(db, 1, &error), qPrintable(error));
            {
                QSqlQuery q(db);
                QVERIFY(q.prepare(QStringLiteral(
                    "INSERT INTO measured_parts (machine_id, part_name, measured_at, measured_by, method, "
                    "project_json, note) VALUES ('haas-st-20', 'Stepped shaft', '2026-01-02T03:04:05.000Z', 'old', "
                    "'micrometer', ?, '')")));
                q.bindValue(0, QString::fromUtf8(exampleProject()));
                QVERIFY2(q.exec(), qPrintable(q.lastError().text()));
            }
            db.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("v1"));
        auto store = openStore(l);
        QVERIFY(store);
        QCOMPARE(store->schemaVersion(), kMeasurementSchemaVersion);
        QString error;
        const auto list = store->list({}, &error);
        QVERIFY2(list.has_value(), qPrintable(error));
        QCOMPARE(list->size(), std::size_t{1});
        QCOMPARE(list->front().measuredBy, QStringLiteral("old"));
        // The checksum, worked out here: SHA-256 of the "part" object as compact JSON.
        const QJsonObject part =
            QJsonDocument::fromJson(exampleProject()).object().value(QStringLiteral("part")).toObject();
        const QByteArray sum =
            QCryptographicHash::hash(QJsonDocument(part).toJson(QJsonDocument::Compact), QCryptographicHash::Sha256)
                .toHex();
        QSqlQuery q(QSqlDatabase::database(QSqlDatabase::connectionNames().constLast()));
        QVERIFY(q.exec(QStringLiteral("SELECT profile_sha256 FROM measured_parts")) && q.next());
        QCOMPARE(q.value(0).toString(), QString::fromLatin1(sum));
    }

    // A store written by a newer TolTurn is refused, not damaged.
    void refusesANewerSchema()
    {
        const StoreLocation l = freshLocation();
        {
            auto store = openStore(l);
            QVERIFY(store);
            QSqlQuery q(QSqlDatabase::database(QSqlDatabase::connectionNames().constLast()));
            QVERIFY(q.exec(QStringLiteral("UPDATE tolturn_schema SET version = 99")));
        }
        QString error;
        QVERIFY(!MeasurementStore::open(l, &error));
        QVERIFY2(error.contains(
                     QStringLiteral("schema version 99, newer than this program's %1").arg(kMeasurementSchemaVersion)),
                 qPrintable(error));
    }

    // Two writers at once, each with its own connection (as two programs would): every part
    // stored whole, none lost, the store consistent.
    void concurrentWritersKeepTheStoreWhole()
    {
        const StoreLocation l = freshLocation();
        QVERIFY(openStore(l)); // created and migrated once
        constexpr int kParts = 30;
        auto writer = [l] {
            QString error;
            auto store = MeasurementStore::open(l, &error);
            if (!store)
                return;
            Diagnostics problems;
            for (int i = 0; i < kParts; ++i)
                (void)store->add(measuredShaft(), problems);
        };
        std::unique_ptr<QThread> a(QThread::create(writer));
        std::unique_ptr<QThread> b(QThread::create(writer));
        a->start();
        b->start();
        QVERIFY(a->wait(120000) && b->wait(120000));
        auto store = openStore(l);
        QString error;
        QCOMPARE(store->count({}, &error).value_or(-1), qint64{2} * kParts);
        QSqlQuery q(QSqlDatabase::database(QSqlDatabase::connectionNames().constLast()));
        QVERIFY(q.exec(QStringLiteral("SELECT COUNT(*) FROM measured_points")) && q.next());
        QCOMPARE(q.value(0).toInt(), 2 * kParts * static_cast<int>(measuredShaft().points.size()));
        QFETCH_GLOBAL(QString, backend);
        if (backend == QLatin1String("sqlite")) {
            QVERIFY(q.exec(QStringLiteral("PRAGMA integrity_check")) && q.next());
            QCOMPARE(q.value(0).toString(), QStringLiteral("ok"));
        }
    }

    // Unset texts (no one named, no method) are stored as empty, not refused as missing.
    void storesAPartWithoutTexts()
    {
        auto store = openStore(freshLocation());
        QVERIFY(store);
        MeasuredPart p = measuredShaft();
        p.measuredBy = QString();
        p.method = QString();
        p.note = QString();
        Diagnostics problems;
        const auto id = store->add(p, problems);
        QVERIFY2(id.has_value(), qPrintable(problems.empty() ? QString() : problems.back().toString()));
        QString error;
        QVERIFY(store->part(*id, &error)->measuredBy.isEmpty());
    }

    // Learned models are kept per machine; the newest is the one in use.
    void keepsLearnedModels()
    {
        auto store = openStore(freshLocation());
        QVERIFY(store);
        QString error;
        QVERIFY(!store->latestLearnedModel(QStringLiteral("haas-st-20"), &error).has_value());
        QVERIFY(error.isEmpty());
        LearnedModelRecord older{0,
                                 QStringLiteral("haas-st-20"),
                                 QDateTime(QDate(2026, 11, 1), QTime(9, 0), Qt::UTC),
                                 12,
                                 144,
                                 0.004,
                                 0.0012,
                                 QByteArray("{\"geometric\": 1}")};
        LearnedModelRecord newer = older;
        newer.trainedAt = older.trainedAt.addDays(7);
        newer.parts = 20;
        QVERIFY(store->addLearnedModel(newer, &error).has_value());
        QVERIFY(store->addLearnedModel(older, &error).has_value());
        const auto latest = store->latestLearnedModel(QStringLiteral("haas-st-20"), &error);
        QVERIFY2(latest.has_value(), qPrintable(error));
        QCOMPARE(latest->parts, 20);
        QCOMPARE(latest->trainedAt, newer.trainedAt);
        QCOMPARE(latest->modelJson, older.modelJson);
        QCOMPARE(latest->learnedRms_mm, 0.0012);
        QVERIFY(!store->latestLearnedModel(QStringLiteral("haas-st-30"), &error).has_value());
    }

    // A store as a user writes it: a file, or a PostgreSQL address as libpq takes it.
    void readsStoreAddresses()
    {
        QString error;
        const auto file = storeLocationFromText(QStringLiteral("/data/shop.sqlite"), &error);
        QVERIFY(file && file->kind == StoreLocation::Kind::SQLite && file->file == QLatin1String("/data/shop.sqlite"));
        const auto pg =
            storeLocationFromText(QStringLiteral("postgresql://planner:s%40cret@db.shop.local:5433/history"), &error);
        QVERIFY(pg.has_value());
        QCOMPARE(pg->kind, StoreLocation::Kind::PostgreSQL);
        QCOMPARE(pg->host, QStringLiteral("db.shop.local"));
        QCOMPARE(pg->port, 5433);
        QCOMPARE(pg->database, QStringLiteral("history"));
        QCOMPARE(pg->user, QStringLiteral("planner"));
        QCOMPARE(pg->password, QStringLiteral("s@cret"));
        QCOMPARE(pg->describe(), QStringLiteral("postgresql://planner@db.shop.local:5433/history"));
        const auto socket = storeLocationFromText(
            QStringLiteral("postgres://planner@localhost/history?host=/var/run/postgresql"), &error);
        QVERIFY(socket.has_value());
        QCOMPARE(socket->host, QStringLiteral("/var/run/postgresql"));
        QCOMPARE(socket->port, 5432);
        QVERIFY(!storeLocationFromText(QStringLiteral("postgresql://db.shop.local/history"), &error)); // no user
        QVERIFY(error.contains(QStringLiteral("is not a PostgreSQL address")));
        QVERIFY(!storeLocationFromText(QStringLiteral("postgresql://planner@db.shop.local"), &error)); // no database
    }

    // An unreachable database: a named error, no store.
    void unreachableStoreIsNamed()
    {
        StoreLocation l;
        l.kind = StoreLocation::Kind::PostgreSQL;
        l.host = m_dir.filePath(QStringLiteral("no-server-here"));
        l.port = 5999;
        l.database = QStringLiteral("shop");
        l.user = QStringLiteral("planner");
        QString error;
        QVERIFY(!MeasurementStore::open(l, &error));
        QVERIFY2(error.contains(QStringLiteral("postgresql://planner@")), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestMeasurementStore)
#include "tst_measurement_store.moc"
