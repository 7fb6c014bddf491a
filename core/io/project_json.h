// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/project/project.h"

#include <QByteArray>
#include <QJsonObject>
#include <QJsonValue>

#include <optional>

namespace tolturn {

// The project file format (docs/project-format.md): JSON, identified by "format" and "version".
// Version 2 adds operations (set-ups) and the held end of a clamping; version 1 files are read as
// projects of one operation held at their left end.
inline constexpr int kProjectFormatVersion = 2;
inline constexpr char kProjectFormatName[] = "tolturn-project";

struct ProjectParseResult {
    std::optional<Project> project; // set only when there are no errors
    // A TolTurn project with errors in its values, as far as it could be read (a value that could
    // not be read is left at its default): for a program that lets the user repair it, never to
    // compute with. Unset for a file that is not a TolTurn project (bad JSON, another format or
    // version) and when `project` is set.
    std::optional<Project> repairable;
    Diagnostics diagnostics;
};

// Parses and validates a project document. Structural problems (bad JSON, wrong types,
// unknown keywords) are reported first; the semantic checks of validateProject() run only on a
// document that parsed cleanly, so one mistake gives one message.
[[nodiscard]] ProjectParseResult parseProjectJson(const QByteArray &json);

// The document for a project, indented, with keys in a stable order.
[[nodiscard]] QByteArray serializeProjectJson(const Project &project);
[[nodiscard]] QJsonObject projectJsonObject(const Project &project);

// One milled feature as the project writes it in "milled_features", and back: `path` names the
// object in the findings (a bad or unknown field is a diagnostic in `out`, its value left at its
// default). For documents that carry features outside a project (core/io/cad_import_json.h).
[[nodiscard]] QJsonObject milledFeatureJson(const MilledFeature &feature);
[[nodiscard]] MilledFeature milledFeatureFromJson(const QJsonObject &json, const QString &path, Diagnostics &out);

// The value a project would write at `field` (a finding's path, "part.outer[2].to.r_mm");
// undefined where it writes none (an unset optional value, an index past the list).
[[nodiscard]] QJsonValue projectValueAt(const Project &project, const QString &field);

} // namespace tolturn
