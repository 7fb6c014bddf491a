// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/measurements/measurement_store.h"

#include "core/io/project_json.h"
#include "core/measurements/measurement_schema.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QUrl>
#include <QUrlQuery>
#include <QVariant>

#include <atomic>
#include <cmath>
#include <utility>

namespace tolturn {

namespace {

constexpr int kPostgresConnectTimeout_s = 5;

struct MeasurementStoreText {
    Q_DECLARE_TR_FUNCTIONS(MeasurementStore)
};

// How long a writer waits for another process's transaction on an SQLite store.
constexpr int kSqliteBusyTimeout_ms = 10000;

QString nextConnectionName()
{
    static std::atomic<int> counter{0};
    return QStringLiteral("tolturn-measurements-%1").arg(counter++);
}

QVariant optionalValue(const std::optional<double> &v)
{
    return v ? QVariant(*v) : QVariant(QMetaType(QMetaType::Double));
}

std::optional<double> optionalFrom(const QVariant &v)
{
    return v.isNull() ? std::nullopt : std::optional<double>(v.toDouble());
}

// An unset text as an empty one: Qt binds a null QString as SQL NULL.
QString textValue(const QString &s)
{
    return s.isNull() ? QStringLiteral("") : s;
}

QString timeText(const QDateTime &t)
{
    return t.toUTC().toString(Qt::ISODateWithMs);
}

QString failure(const QString &what, const QSqlError &e)
{
    return QStringLiteral("%1: %2").arg(what, e.text());
}

// The WHERE clause of a filter's machine and its value. The text is matched here, in Qt, not in
// SQL: SQLite's LOWER folds ASCII only, and LIKE would take % and _ in what was typed as wildcards.
QString whereOf(const PartFilter &f, QVariantList &values)
{
    if (f.machineId.isEmpty())
        return {};
    values << f.machineId;
    return QStringLiteral(" WHERE machine_id = ?");
}

bool matchesText(const MeasuredPartSummary &s, const QString &text)
{
    return text.isEmpty() || s.partName.contains(text, Qt::CaseInsensitive) ||
           s.measuredBy.contains(text, Qt::CaseInsensitive) || s.method.contains(text, Qt::CaseInsensitive);
}

bool prepareAndRun(QSqlQuery &q, const QString &sql, const QVariantList &values)
{
    if (!q.prepare(sql))
        return false;
    for (qsizetype i = 0; i < values.size(); ++i)
        q.bindValue(static_cast<int>(i), values.at(i));
    return q.exec();
}

} // namespace

QString StoreLocation::describe() const
{
    if (kind == Kind::SQLite)
        return QDir::toNativeSeparators(file);
    return QStringLiteral("postgresql://%1@%2:%3/%4").arg(user, host).arg(port).arg(database);
}

std::optional<StoreLocation> storeLocationFromText(const QString &text, QString *error)
{
    StoreLocation l;
    if (!text.startsWith(QLatin1String("postgresql://")) && !text.startsWith(QLatin1String("postgres://"))) {
        if (text.trimmed().isEmpty()) {
            if (error)
                *error = MeasurementStoreText::tr("the store is not named");
            return std::nullopt;
        }
        l.file = text;
        return l;
    }
    const QUrl url(text, QUrl::StrictMode);
    const QString database = url.path().mid(1);
    if (!url.isValid() || url.host(QUrl::FullyDecoded).isEmpty() || url.userName().isEmpty() || database.isEmpty()) {
        if (error)
            *error = MeasurementStoreText::tr("\"%1\" is not a PostgreSQL address of the form "
                                              "postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE[?host=SOCKET_FOLDER]")
                         .arg(url.toDisplayString(QUrl::RemovePassword));
        return std::nullopt;
    }
    l.kind = StoreLocation::Kind::PostgreSQL;
    // libpq's way to name a Unix socket's folder: ?host=/var/run/postgresql (a host is a name).
    const QString socketFolder = QUrlQuery(url).queryItemValue(QStringLiteral("host"), QUrl::FullyDecoded);
    l.host = socketFolder.isEmpty() ? url.host(QUrl::FullyDecoded) : socketFolder;
    l.port = url.port(5432);
    l.database = database;
    l.user = url.userName(QUrl::FullyDecoded);
    l.password = url.password(QUrl::FullyDecoded);
    return l;
}

StoreLocation defaultStoreLocation()
{
    StoreLocation l;
    // One file for the desktop program and the command line (their application names differ, so
    // AppDataLocation would give each its own).
    l.file = QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation))
                 .filePath(QStringLiteral("TolTurn/measurements.sqlite"));
    return l;
}

MeasurementStore::MeasurementStore(StoreLocation location, QString connection)
    : m_location(std::move(location))
    , m_connection(std::move(connection))
{
}

MeasurementStore::~MeasurementStore()
{
    {
        QSqlDatabase database = db();
        database.close();
    }
    QSqlDatabase::removeDatabase(m_connection);
}

QSqlDatabase MeasurementStore::db() const
{
    return QSqlDatabase::database(m_connection, false);
}

std::unique_ptr<MeasurementStore> MeasurementStore::open(const StoreLocation &location, QString *error)
{
    const bool sqlite = location.kind == StoreLocation::Kind::SQLite;
    const QString driver = sqlite ? QStringLiteral("QSQLITE") : QStringLiteral("QPSQL");
    const auto refuse = [&](const QString &why) -> std::unique_ptr<MeasurementStore> {
        if (error)
            *error = MeasurementStoreText::tr("cannot open the measurement store %1: %2").arg(location.describe(), why);
        return nullptr;
    };
    if (!QSqlDatabase::isDriverAvailable(driver))
        return refuse(
            sqlite ? MeasurementStoreText::tr("Qt's SQLite driver is not installed (Debian: libqt6sql6-sqlite)")
                   : MeasurementStoreText::tr("Qt's PostgreSQL driver is not installed (Debian: libqt6sql6-psql)"));
    if (sqlite && !QDir().mkpath(QFileInfo(location.file).absolutePath()))
        return refuse(
            MeasurementStoreText::tr("cannot create the folder %1").arg(QFileInfo(location.file).absolutePath()));
    const QString name = nextConnectionName();
    std::unique_ptr<MeasurementStore> store(new MeasurementStore(location, name));
    QSqlDatabase db = QSqlDatabase::addDatabase(driver, name);
    if (sqlite) {
        db.setDatabaseName(location.file);
        db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=%1").arg(kSqliteBusyTimeout_ms));
    } else {
        db.setHostName(location.host);
        db.setPort(location.port);
        db.setDatabaseName(location.database);
        db.setUserName(location.user);
        db.setPassword(location.password);
        // libpq waits for a host that does not answer as long as TCP does (minutes); a shop
        // database that cannot be reached is named within seconds instead.
        db.setConnectOptions(QStringLiteral("connect_timeout=%1").arg(kPostgresConnectTimeout_s));
    }
    if (!db.open())
        return refuse(db.lastError().text());
    QSqlQuery q(db);
    // SQLite: references enforced (its default is off), and a write-ahead log so that readers do
    // not block the writer.
    if (sqlite &&
        (!q.exec(QStringLiteral("PRAGMA foreign_keys = ON")) || !q.exec(QStringLiteral("PRAGMA journal_mode = WAL"))))
        return refuse(q.lastError().text());
    q.finish(); // the pragma's result row would hold the migration's commit back
    QString why;
    if (!measurements::migrateSchema(db, kMeasurementSchemaVersion, &why))
        return refuse(why);
    return store;
}

int MeasurementStore::schemaVersion() const
{
    return measurements::schemaVersionOf(db(), nullptr);
}

std::optional<qint64> MeasurementStore::add(const MeasuredPart &part, Diagnostics &problems)
{
    problems = validateMeasuredPart(part);
    if (hasErrors(problems))
        return std::nullopt;
    const ProjectParseResult snapshot = parseProjectJson(part.projectJson);
    QSqlDatabase database = db();
    QSqlQuery q(database);
    const auto fail = [&](const QString &what, const QSqlError &e) -> std::optional<qint64> {
        database.rollback();
        problems.push_back(makeError(QStringLiteral("store"), failure(what, e)));
        return std::nullopt;
    };
    // SQLite: take the write lock now (BEGIN IMMEDIATE), so that two writers queue on the busy
    // timeout instead of one failing when it tries to write inside a read transaction.
    const bool begun = m_location.kind == StoreLocation::Kind::SQLite ? q.exec(QStringLiteral("BEGIN IMMEDIATE"))
                                                                      : database.transaction();
    if (!begun)
        return fail(MeasurementStoreText::tr("cannot start a transaction"),
                    q.lastError().isValid() ? q.lastError() : database.lastError());
    if (!prepareAndRun(
            q,
            QStringLiteral("INSERT INTO measured_parts (machine_id, part_name, measured_at, measured_by, "
                           "method, time_since_start_min, ambient_c, project_json, note, profile_sha256, drive_json) "
                           "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
            {part.machineId, textValue(snapshot.project->part.name), timeText(part.measuredAt),
             textValue(part.measuredBy), textValue(part.method), optionalValue(part.timeSinceStart_min),
             optionalValue(part.ambient_C), QString::fromUtf8(part.projectJson), textValue(part.note),
             measurements::profileChecksum(part.projectJson),
             part.drive ? QVariant(QString::fromUtf8(
                              QJsonDocument(driveReadingJson(*part.drive)).toJson(QJsonDocument::Compact)))
                        : QVariant(QMetaType::fromType<QString>())}))
        return fail(MeasurementStoreText::tr("cannot store the part"), q.lastError());
    const qint64 id = q.lastInsertId().toLongLong();
    for (std::size_t i = 0; i < part.points.size(); ++i) {
        const MeasuredPoint &p = part.points[i];
        const bool cmm = p.quantity == MeasuredQuantity::CmmPoint;
        if (!prepareAndRun(q,
                           QStringLiteral("INSERT INTO measured_points (part_id, seq, feature_id, z_mm, quantity, "
                                          "value_mm, x_mm, y_mm) VALUES (?, ?, ?, ?, ?, ?, ?, ?)"),
                           {id, static_cast<int>(i), p.featureId, p.z_mm, keyword(p.quantity), p.value_mm,
                            optionalValue(cmm ? std::optional(p.x_mm) : std::nullopt),
                            optionalValue(cmm ? std::optional(p.y_mm) : std::nullopt)}))
            return fail(MeasurementStoreText::tr("cannot store point %1").arg(i), q.lastError());
    }
    if (m_location.kind == StoreLocation::Kind::SQLite ? !q.exec(QStringLiteral("COMMIT")) : !database.commit())
        return fail(MeasurementStoreText::tr("cannot commit the part"),
                    q.lastError().isValid() ? q.lastError() : database.lastError());
    return id;
}

std::optional<MeasuredPart> MeasurementStore::part(qint64 id, QString *error) const
{
    QSqlQuery q(db());
    const auto fail = [error](const QString &why) -> std::optional<MeasuredPart> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (!prepareAndRun(q,
                       QStringLiteral("SELECT machine_id, measured_at, measured_by, method, time_since_start_min, "
                                      "ambient_c, project_json, note, drive_json FROM measured_parts WHERE id = ?"),
                       {id}))
        return fail(failure(MeasurementStoreText::tr("cannot read part %1").arg(id), q.lastError()));
    if (!q.next())
        return fail(MeasurementStoreText::tr("the store has no part %1").arg(id));
    MeasuredPart p;
    p.id = id;
    p.machineId = q.value(0).toString();
    p.measuredAt = QDateTime::fromString(q.value(1).toString(), Qt::ISODateWithMs);
    p.measuredBy = q.value(2).toString();
    p.method = q.value(3).toString();
    p.timeSinceStart_min = optionalFrom(q.value(4));
    p.ambient_C = optionalFrom(q.value(5));
    p.projectJson = q.value(6).toString().toUtf8();
    p.note = q.value(7).toString();
    if (!q.value(8).isNull()) {
        QString why;
        p.drive = driveReadingFromJson(QJsonDocument::fromJson(q.value(8).toString().toUtf8()).object(), &why);
        if (!p.drive)
            return fail(MeasurementStoreText::tr("part %1 has a damaged drive reading: %2").arg(id).arg(why));
    }
    if (!prepareAndRun(
            q,
            QStringLiteral("SELECT feature_id, z_mm, quantity, value_mm, x_mm, y_mm FROM measured_points WHERE "
                           "part_id = ? ORDER BY seq"),
            {id}))
        return fail(failure(MeasurementStoreText::tr("cannot read the points of part %1").arg(id), q.lastError()));
    while (q.next()) {
        const auto quantity = measuredQuantityFromKeyword(q.value(2).toString());
        if (!quantity)
            return fail(MeasurementStoreText::tr("part %1 has a point of unknown quantity \"%2\"")
                            .arg(id)
                            .arg(q.value(2).toString()));
        p.points.push_back({q.value(0).toString(), q.value(1).toDouble(), *quantity, q.value(3).toDouble(),
                            q.value(4).toDouble(), q.value(5).toDouble()});
    }
    return p;
}

std::optional<std::vector<MeasuredPart>> MeasurementStore::parts(const std::vector<qint64> &ids, QString *error) const
{
    std::vector<MeasuredPart> out;
    for (const qint64 id : ids) {
        auto p = part(id, error);
        if (!p)
            return std::nullopt;
        out.push_back(std::move(*p));
    }
    return out;
}

std::optional<std::vector<MeasuredPartSummary>> MeasurementStore::list(const PartFilter &filter, QString *error) const
{
    QVariantList values;
    QString sql = QStringLiteral("SELECT p.id, p.machine_id, p.part_name, p.measured_at, p.measured_by, p.method, "
                                 "(SELECT COUNT(*) FROM measured_points m WHERE m.part_id = p.id) FROM "
                                 "measured_parts p") +
                  whereOf(filter, values) + QStringLiteral(" ORDER BY p.measured_at DESC, p.id DESC");
    const bool paged = filter.limit >= 0 && filter.text.isEmpty(); // else paged after the text match
    if (paged)
        sql += QStringLiteral(" LIMIT %1 OFFSET %2").arg(filter.limit).arg(std::max(0, filter.offset));
    QSqlQuery q(db());
    q.setForwardOnly(true);
    if (!prepareAndRun(q, sql, values)) {
        if (error)
            *error = failure(MeasurementStoreText::tr("cannot list the parts"), q.lastError());
        return std::nullopt;
    }
    std::vector<MeasuredPartSummary> out;
    int skipped = 0;
    while (q.next()) {
        MeasuredPartSummary s{q.value(0).toLongLong(), q.value(1).toString(),
                              q.value(2).toString(),   QDateTime::fromString(q.value(3).toString(), Qt::ISODateWithMs),
                              q.value(4).toString(),   q.value(5).toString(),
                              q.value(6).toInt()};
        if (!paged && !matchesText(s, filter.text))
            continue;
        if (!paged && skipped < filter.offset) {
            ++skipped;
            continue;
        }
        out.push_back(std::move(s));
        if (!paged && filter.limit >= 0 && static_cast<int>(out.size()) >= filter.limit)
            break;
    }
    return out;
}

std::optional<qint64> MeasurementStore::count(const PartFilter &filter, QString *error) const
{
    if (!filter.text.isEmpty()) {
        PartFilter all = filter;
        all.limit = -1;
        all.offset = 0;
        const auto parts = list(all, error);
        return parts ? std::optional<qint64>(static_cast<qint64>(parts->size())) : std::nullopt;
    }
    QVariantList values;
    QSqlQuery q(db());
    if (!prepareAndRun(q, QStringLiteral("SELECT COUNT(*) FROM measured_parts") + whereOf(filter, values), values) ||
        !q.next()) {
        if (error)
            *error = failure(MeasurementStoreText::tr("cannot count the parts"), q.lastError());
        return std::nullopt;
    }
    return q.value(0).toLongLong();
}

bool MeasurementStore::remove(qint64 id, QString *error)
{
    QSqlQuery q(db());
    if (!prepareAndRun(q, QStringLiteral("DELETE FROM measured_parts WHERE id = ?"), {id})) {
        if (error)
            *error = failure(MeasurementStoreText::tr("cannot remove part %1").arg(id), q.lastError());
        return false;
    }
    if (q.numRowsAffected() < 1) {
        if (error)
            *error = MeasurementStoreText::tr("the store has no part %1").arg(id);
        return false;
    }
    return true;
}

std::optional<qint64> MeasurementStore::addLearnedModel(const LearnedModelRecord &model, QString *error)
{
    QSqlQuery q(db());
    if (model.machineId.isEmpty() || !std::isfinite(model.physicsRms_mm) || !std::isfinite(model.learnedRms_mm)) {
        if (error)
            *error = MeasurementStoreText::tr("a learned model needs its machine and finite figures");
        return std::nullopt;
    }
    if (!prepareAndRun(q,
                       QStringLiteral("INSERT INTO learned_models (machine_id, trained_at, parts, points, "
                                      "physics_rms_mm, learned_rms_mm, model_json) VALUES (?, ?, ?, ?, ?, ?, ?)"),
                       {model.machineId, timeText(model.trainedAt), model.parts, model.points, model.physicsRms_mm,
                        model.learnedRms_mm, QString::fromUtf8(model.modelJson)})) {
        if (error)
            *error = failure(MeasurementStoreText::tr("cannot keep the learned model"), q.lastError());
        return std::nullopt;
    }
    return q.lastInsertId().toLongLong();
}

std::optional<LearnedModelRecord> MeasurementStore::latestLearnedModel(const QString &machineId, QString *error) const
{
    QSqlQuery q(db());
    if (!prepareAndRun(q,
                       QStringLiteral("SELECT id, trained_at, parts, points, physics_rms_mm, learned_rms_mm, "
                                      "model_json FROM learned_models WHERE machine_id = ? ORDER BY trained_at DESC, "
                                      "id DESC LIMIT 1"),
                       {machineId})) {
        if (error)
            *error = failure(MeasurementStoreText::tr("cannot read the learned models"), q.lastError());
        return std::nullopt;
    }
    if (!q.next())
        return std::nullopt;
    LearnedModelRecord r;
    r.id = q.value(0).toLongLong();
    r.machineId = machineId;
    r.trainedAt = QDateTime::fromString(q.value(1).toString(), Qt::ISODateWithMs);
    r.parts = q.value(2).toInt();
    r.points = q.value(3).toInt();
    r.physicsRms_mm = q.value(4).toDouble();
    r.learnedRms_mm = q.value(5).toDouble();
    r.modelJson = q.value(6).toString().toUtf8();
    return r;
}

} // namespace tolturn
