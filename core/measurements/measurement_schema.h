// SPDX-License-Identifier: GPL-3.0-or-later
// Private to core/measurements: the versions of the store's schema and the steps between them.
#pragma once

#include <QSqlDatabase>
#include <QString>

namespace tolturn::measurements {

// The schema version of an open database: 0 when it holds no TolTurn tables yet.
[[nodiscard]] int schemaVersionOf(const QSqlDatabase &db, QString *error);

// Brings the database from its version to `target`, one step at a time, each in a transaction:
//  1: measured_parts (one row a part, with its project snapshot) and measured_points;
//  2: measured_parts.profile_sha256, the checksum of the snapshot's profile (a part whose profile
//     no longer matches the project is told apart without parsing every snapshot), filled for
//     the parts already stored; and an index on
//     (machine_id, measured_at) for the listing of a machine's parts, newest first;
//  3: learned_models, what `learn --save` keeps of a machine (the model as JSON, with the parts,
//     points and cross-validation figures it came with).
// A database newer than `target` is refused.
[[nodiscard]] bool migrateSchema(QSqlDatabase &db, int target, QString *error);

// The checksum of a project snapshot's profile: SHA-256 of its "part" object as compact JSON
// (Qt writes object keys sorted, so equal profiles give equal sums). Empty for a snapshot that
// is not JSON with a "part" object.
[[nodiscard]] QString profileChecksum(const QByteArray &projectJson);

} // namespace tolturn::measurements
