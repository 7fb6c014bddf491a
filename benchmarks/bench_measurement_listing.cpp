// SPDX-License-Identifier: GPL-3.0-or-later
// Scale of the measurement history (issue 15), results recorded in docs/benchmarks.md: a store of
// 100 000 measured parts (each with its project snapshot and 15 points) listed and filtered by the
// store, and by the Measurements dock, which reads in a worker thread: how long until the rows are
// shown, and the longest the window's event loop is held up meanwhile (a 5 ms timer's largest gap).
// Run: build/<preset>/benchmarks/bench_measurement_listing [PARTS]   (QT_QPA_PLATFORM=offscreen)
#include "benchmarks/bench_timing.h"

#include "core/io/project_file.h"
#include "core/io/project_json.h"
#include "core/measurements/measurement_store.h"
#include "widgets/measurements/measured_parts_model.h"
#include "widgets/measurements/measurements_panel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <cstdio>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

namespace {

constexpr int kPointsPerPart = 15;
constexpr int kPlanners = 20;

// The parts written in one transaction straight through SQL (MeasurementStore::add commits each
// part on its own, which on a disk that syncs each commit takes minutes for 10⁵ parts).
bool fill(const QString &file, int parts, const QByteArray &snapshot)
{
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("fill"));
    db.setDatabaseName(file);
    if (!db.open() || !db.transaction())
        return false;
    QSqlQuery part(db);
    QSqlQuery point(db);
    part.prepare(QStringLiteral("INSERT INTO measured_parts (machine_id, part_name, measured_at, measured_by, method, "
                                "time_since_start_min, ambient_c, project_json, note, profile_sha256) VALUES (?, ?, ?, "
                                "?, ?, ?, ?, ?, '', '')"));
    point.prepare(QStringLiteral(
        "INSERT INTO measured_points (part_id, seq, feature_id, z_mm, quantity, value_mm) VALUES (?, ?, 'O4', ?, "
        "'diameter', 50.004)"));
    const QDateTime start(QDate(2020, 1, 1), QTime(6, 0), Qt::UTC);
    const QString json = QString::fromUtf8(snapshot);
    for (int i = 0; i < parts; ++i) {
        const QVariantList values{i % 4 == 0 ? QStringLiteral("haas-st-30") : QStringLiteral("haas-st-20"),
                                  QStringLiteral("Shaft %1").arg(i % 500),
                                  start.addSecs(600LL * i).toString(Qt::ISODateWithMs),
                                  QStringLiteral("Planner %1").arg(i % kPlanners),
                                  QStringLiteral("micrometer"),
                                  30.0,
                                  20.0,
                                  json};
        for (int k = 0; k < static_cast<int>(values.size()); ++k)
            part.bindValue(k, values.at(k));
        if (!part.exec())
            return false;
        const qint64 id = part.lastInsertId().toLongLong();
        for (int s = 0; s < kPointsPerPart; ++s) {
            point.bindValue(0, id);
            point.bindValue(1, s);
            point.bindValue(2, 35.0 + 3.0 * s);
            if (!point.exec())
                return false;
        }
    }
    return db.commit();
}

struct DockTiming {
    double shown_ms = 0.0;      // from the request to the rows in the table
    double longestGap_ms = 0.0; // the event loop's longest stall meanwhile
    int rows = 0;
};

// Asks the dock for a listing (`ask`) and runs the event loop until it is shown.
template <typename Ask>
DockTiming timeDock(MeasurementsPanel &panel, Ask ask)
{
    DockTiming t;
    QEventLoop loop;
    QObject::connect(&panel, &MeasurementsPanel::listingFinished, &loop, &QEventLoop::quit);
    QTimer tick;
    tick.setInterval(5);
    QElapsedTimer clock;
    qint64 last = 0;
    QObject::connect(&tick, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        t.longestGap_ms = std::max(t.longestGap_ms, 1e-6 * static_cast<double>(now - last));

        last = now;
    });
    clock.start();
    tick.start();
    ask();
    // The gap of the call itself counts too: it runs on the window's thread.
    t.longestGap_ms = std::max(t.longestGap_ms, 1e-6 * static_cast<double>(clock.nsecsElapsed()));

    last = clock.nsecsElapsed();
    loop.exec();
    t.shown_ms = 1e-6 * static_cast<double>(clock.nsecsElapsed());
    t.rows = panel.partsModel()->rowCount();
    return t;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    const int parts = argc > 1 ? std::max(1, QString::fromLocal8Bit(argv[1]).toInt()) : 100000;
    const QString example = QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn");
    const auto project = readProjectFile(example).project;
    QTemporaryDir dir;
    if (!project || !dir.isValid())
        return 1;
    StoreLocation location;
    location.file = dir.filePath(QStringLiteral("bench.sqlite"));
    QString error;
    {
        const auto created = MeasurementStore::open(location, &error);
        if (!created) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 1;
        }
    }
    QElapsedTimer filling;
    filling.start();
    if (!fill(location.file, parts, serializeProjectJson(*project)))
        return 1;
    QSqlDatabase::removeDatabase(QStringLiteral("fill"));
    std::printf("store of %d parts (%d points each, with their snapshots) written in %.1f s\n", parts, kPointsPerPart,
                1e-3 * static_cast<double>(filling.elapsed()));

    const auto store = MeasurementStore::open(location, &error);
    std::size_t rows = 0;
    PartFilter machine;
    machine.machineId = QStringLiteral("haas-st-20");
    const double all = medianMilliseconds(3, [&] { rows = store->list(machine, nullptr)->size(); });
    std::printf("store: list the %zu parts of one machine: %.0f ms (median of 3)\n", rows, all);
    PartFilter text = machine;
    text.text = QStringLiteral("planner 7");
    const double filtered = medianMilliseconds(3, [&] { rows = store->list(text, nullptr)->size(); });
    std::printf("store: the same filtered by \"planner 7\" (%zu parts): %.0f ms (median of 3)\n", rows, filtered);

    MeasurementsPanel panel;
    panel.resize(900, 500);
    panel.show();
    const DockTiming first = timeDock(panel, [&] {
        panel.setStoreLocation(location);
        panel.setProject(&*project);
    });
    std::printf("dock: %d rows shown %.0f ms after the request; the window's event loop was held up at most %.0f ms\n",
                first.rows, first.shown_ms, first.longestGap_ms);
    const DockTiming typed = timeDock(panel, [&] { panel.setFilterText(QStringLiteral("planner 7")); });
    std::printf("dock: filtered to %d rows %.0f ms after typing; held up at most %.0f ms\n", typed.rows, typed.shown_ms,
                typed.longestGap_ms);
    return 0;
}
