// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/measurements/measurement_schema.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>
#include <QVariant>

#include <utility>
#include <vector>

namespace tolturn::measurements {

namespace {

struct MeasurementSchema {
    Q_DECLARE_TR_FUNCTIONS(MeasurementSchema)
};

bool isPostgres(const QSqlDatabase &db)
{
    return db.driverName() == QLatin1String("QPSQL");
}

bool run(QSqlQuery &q, const QString &sql, QString *error)
{
    if (q.exec(sql))
        return true;
    if (error)
        *error = MeasurementSchema::tr("the store refused \"%1\": %2").arg(sql.simplified(), q.lastError().text());
    return false;
}

// Version 1: the parts and their points. The only difference between the two databases is the
// generated key: SQLite's INTEGER PRIMARY KEY is its row id, PostgreSQL's BIGSERIAL a sequence.
QStringList version1(const QSqlDatabase &db)
{
    const QString key =
        isPostgres(db) ? QStringLiteral("BIGSERIAL PRIMARY KEY") : QStringLiteral("INTEGER PRIMARY KEY");
    return {QStringLiteral("CREATE TABLE tolturn_schema (version INTEGER NOT NULL)"),
            QStringLiteral("INSERT INTO tolturn_schema (version) VALUES (0)"),
            QStringLiteral("CREATE TABLE measured_parts (id %1, machine_id TEXT NOT NULL, part_name TEXT NOT NULL, "
                           "measured_at TEXT NOT NULL, measured_by TEXT NOT NULL, method TEXT NOT NULL, "
                           "time_since_start_min DOUBLE PRECISION, ambient_c DOUBLE PRECISION, "
                           "project_json TEXT NOT NULL, note TEXT NOT NULL)")
                .arg(key),
            QStringLiteral("CREATE TABLE measured_points (part_id BIGINT NOT NULL REFERENCES measured_parts (id) ON "
                           "DELETE CASCADE, seq INTEGER NOT NULL, feature_id TEXT NOT NULL, z_mm DOUBLE PRECISION "
                           "NOT NULL, quantity TEXT NOT NULL, value_mm DOUBLE PRECISION NOT NULL, PRIMARY KEY "
                           "(part_id, seq))")};
}

// Version 3: what was learned of each machine, newest last (docs/learning.md).
QStringList version3(const QSqlDatabase &db)
{
    const QString key =
        isPostgres(db) ? QStringLiteral("BIGSERIAL PRIMARY KEY") : QStringLiteral("INTEGER PRIMARY KEY");
    return {QStringLiteral("CREATE TABLE learned_models (id %1, machine_id TEXT NOT NULL, trained_at TEXT NOT NULL, "
                           "parts INTEGER NOT NULL, points INTEGER NOT NULL, physics_rms_mm DOUBLE PRECISION NOT "
                           "NULL, learned_rms_mm DOUBLE PRECISION NOT NULL, model_json TEXT NOT NULL)")
                .arg(key)};
}

// Version 4: CMM points (x and y across the axis; value_mm keeps their radius) and the drive
// readings of a part's cut (spindle and feed motor currents, Li & Du eq. 7–14, as JSON).
QStringList version4()
{
    return {QStringLiteral("ALTER TABLE measured_points ADD COLUMN x_mm DOUBLE PRECISION"),
            QStringLiteral("ALTER TABLE measured_points ADD COLUMN y_mm DOUBLE PRECISION"),
            QStringLiteral("ALTER TABLE measured_parts ADD COLUMN drive_json TEXT")};
}

QStringList version2()
{
    return {QStringLiteral("ALTER TABLE measured_parts ADD COLUMN profile_sha256 TEXT"),
            QStringLiteral("CREATE INDEX measured_parts_by_machine ON measured_parts (machine_id, measured_at)")};
}

// The checksums of the parts stored before version 2.
bool fillProfileChecksums(QSqlDatabase &db, QString *error)
{
    QSqlQuery select(db);
    select.setForwardOnly(true);
    if (!run(select, QStringLiteral("SELECT id, project_json FROM measured_parts WHERE profile_sha256 IS NULL"), error))
        return false;
    std::vector<std::pair<qint64, QString>> sums;
    while (select.next())
        sums.emplace_back(select.value(0).toLongLong(), profileChecksum(select.value(1).toString().toUtf8()));
    select.finish();
    QSqlQuery update(db);
    if (!update.prepare(QStringLiteral("UPDATE measured_parts SET profile_sha256 = ? WHERE id = ?")))
        return run(update, update.lastQuery(), error);
    for (const auto &[id, sum] : sums) {
        update.bindValue(0, sum);
        update.bindValue(1, id);
        if (!update.exec()) {
            if (error)
                *error = MeasurementSchema::tr("the store refused the checksum of part %1: %2")
                             .arg(id)
                             .arg(update.lastError().text());
            return false;
        }
    }
    return true;
}

bool step(QSqlDatabase &db, int to, QString *error)
{
    QSqlQuery q(db);
    const QStringList statements = to == 1 ? version1(db) : to == 2 ? version2() : to == 3 ? version3(db) : version4();
    for (const QString &sql : statements) {
        if (!run(q, sql, error))
            return false;
    }
    if (to == 2 && !fillProfileChecksums(db, error))
        return false;
    return run(q, QStringLiteral("UPDATE tolturn_schema SET version = %1").arg(to), error);
}

} // namespace

int schemaVersionOf(const QSqlDatabase &db, QString *error)
{
    QSqlQuery q(db);
    // PostgreSQL: the table as the search path finds it (QPSQL's tables() names a table outside
    // "public" with its schema, "shop.tolturn_schema").
    if (isPostgres(db)) {
        if (!run(q, QStringLiteral("SELECT to_regclass('tolturn_schema') IS NOT NULL"), error) || !q.next())
            return -1;
        if (!q.value(0).toBool())
            return 0;
    } else if (!db.tables().contains(QStringLiteral("tolturn_schema"))) {
        return 0;
    }
    if (!run(q, QStringLiteral("SELECT version FROM tolturn_schema"), error) || !q.next())
        return -1;
    return q.value(0).toInt();
}

namespace {

// Takes the store for one migration step: SQLite's write lock at once (BEGIN IMMEDIATE), or on
// PostgreSQL a transaction holding an advisory lock, so that two programs opening a new or old
// store at the same time migrate it one after the other; the second then finds it done.
bool beginMigrationStep(QSqlDatabase &db, QString *error)
{
    QSqlQuery q(db);
    if (!isPostgres(db))
        return run(q, QStringLiteral("BEGIN IMMEDIATE"), error);
    if (!db.transaction()) {
        if (error)
            *error = db.lastError().text();
        return false;
    }
    // The key: "TolT" in ASCII, TolTurn's lock of its own schema.
    return run(q, QStringLiteral("SELECT pg_advisory_xact_lock(1416588372)"), error);
}

bool endMigrationStep(QSqlDatabase &db, bool commit)
{
    if (isPostgres(db))
        return commit ? db.commit() : db.rollback();
    QSqlQuery q(db);
    return q.exec(commit ? QStringLiteral("COMMIT") : QStringLiteral("ROLLBACK"));
}

} // namespace

bool migrateSchema(QSqlDatabase &db, int target, QString *error)
{
    for (;;) {
        if (!beginMigrationStep(db, error))
            return false;
        // Read under the lock: another program may have migrated meanwhile.
        const int version = schemaVersionOf(db, error);
        if (version < 0 || version > target) {
            if (version > target && error)
                *error = MeasurementSchema::tr("the store has schema version %1, newer than this program's %2: "
                                               "update TolTurn")
                             .arg(version)
                             .arg(target);
            endMigrationStep(db, false);
            return false;
        }
        if (version == target)
            return endMigrationStep(db, true);
        if (!step(db, version + 1, error)) {
            endMigrationStep(db, false);
            return false;
        }
        if (!endMigrationStep(db, true)) {
            if (error)
                *error = db.lastError().text();
            return false;
        }
    }
}

QString profileChecksum(const QByteArray &projectJson)
{
    const QJsonDocument doc = QJsonDocument::fromJson(projectJson);
    const QJsonValue part = doc.object().value(QStringLiteral("part"));
    if (!part.isObject())
        return {};
    return QString::fromLatin1(QCryptographicHash::hash(QJsonDocument(part.toObject()).toJson(QJsonDocument::Compact),
                                                        QCryptographicHash::Sha256)
                                   .toHex());
}

} // namespace tolturn::measurements
