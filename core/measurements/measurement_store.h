// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/measurements/measured_part.h"

#include <QSqlDatabase>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace tolturn {

// Where the measured parts are kept (docs/learning.md): an SQLite file, by default in the
// per-user data folder (no set-up), or a shop's shared PostgreSQL database, through the same code.
struct StoreLocation {
    enum class Kind { SQLite, PostgreSQL };
    Kind kind = Kind::SQLite;
    QString file; // SQLite
    QString host; // PostgreSQL: a host name, or the folder of its Unix socket
    int port = 5432;
    QString database;
    QString user;
    QString password;

    // For messages: the file, or user@host:port/database (never the password).
    [[nodiscard]] QString describe() const;
};

// A store named as a user writes it: "postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE", with
// "?host=/var/run/postgresql" for a Unix socket's folder as libpq has it; otherwise the path of
// an SQLite file. Empty, with `error` set, for a malformed address.
[[nodiscard]] std::optional<StoreLocation> storeLocationFromText(const QString &text, QString *error);

// The per-user SQLite file, shared by the desktop program and the command line:
// <GenericDataLocation>/TolTurn/measurements.sqlite (~/.local/share/TolTurn/… on Linux).
[[nodiscard]] StoreLocation defaultStoreLocation();

// The schema version this program writes; older stores are migrated when opened
// (measurement_schema.h), newer ones are refused.
inline constexpr int kMeasurementSchemaVersion = 4;

struct PartFilter {
    QString machineId; // empty: every machine
    QString text;      // in the part's name, who measured or how; empty: any
    int limit = -1;    // -1: all
    int offset = 0;
};

// What was learned of a machine from its parts (core/learning), as kept in the store.
struct LearnedModelRecord {
    qint64 id = 0;
    QString machineId;
    QDateTime trainedAt; // UTC
    int parts = 0;
    int points = 0;
    double physicsRms_mm = 0.0; // leave one part out, the physics alone
    double learnedRms_mm = 0.0; // and with what was learned
    QByteArray modelJson;       // learnedResidualJson()
};

// The measurement history. Every write is one transaction: a part is stored with all its points
// or not at all, and writers in other processes wait their turn (SQLite: a busy timeout and
// immediate transactions; PostgreSQL: its own locking).
class MeasurementStore {
public:
    // Opens the store, creating an SQLite file and its folder when there is none, and brings its
    // schema to kMeasurementSchemaVersion. Null with `error` set (naming the store) otherwise.
    [[nodiscard]] static std::unique_ptr<MeasurementStore> open(const StoreLocation &location, QString *error);
    ~MeasurementStore();
    MeasurementStore(const MeasurementStore &) = delete;
    MeasurementStore &operator=(const MeasurementStore &) = delete;

    [[nodiscard]] const StoreLocation &location() const { return m_location; }

    [[nodiscard]] int schemaVersion() const;

    // Validates (validateMeasuredPart) and stores the part; its new id, or the problems.
    [[nodiscard]] std::optional<qint64> add(const MeasuredPart &part, Diagnostics &problems);
    [[nodiscard]] std::optional<MeasuredPart> part(qint64 id, QString *error) const;
    // The parts with these ids, in that order; empty with `error` at the first that cannot be read.
    [[nodiscard]] std::optional<std::vector<MeasuredPart>> parts(const std::vector<qint64> &ids, QString *error) const;
    [[nodiscard]] std::optional<std::vector<MeasuredPartSummary>> list(const PartFilter &filter, QString *error) const;
    [[nodiscard]] std::optional<qint64> count(const PartFilter &filter, QString *error) const;
    // False with `error` when there is no such part or the store refused.
    bool remove(qint64 id, QString *error);

    // Keeps a learned model; its new id, or empty with `error`.
    [[nodiscard]] std::optional<qint64> addLearnedModel(const LearnedModelRecord &model, QString *error);
    // The newest learned model of a machine; empty without `error` when there is none.
    [[nodiscard]] std::optional<LearnedModelRecord> latestLearnedModel(const QString &machineId, QString *error) const;

private:
    MeasurementStore(StoreLocation location, QString connection);

    StoreLocation m_location;
    QString m_connection;
    [[nodiscard]] QSqlDatabase db() const;
};

} // namespace tolturn
