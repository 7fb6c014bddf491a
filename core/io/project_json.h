// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/project/project.h"

#include <QByteArray>

#include <optional>

namespace tolturn {

// The project file format (docs/project-format.md): JSON, identified by "format" and "version".
inline constexpr int kProjectFormatVersion = 1;
inline constexpr char kProjectFormatName[] = "tolturn-project";

struct ProjectParseResult {
    std::optional<Project> project; // set only when there are no errors
    Diagnostics diagnostics;
};

// Parses and validates a project document. Structural problems (bad JSON, wrong types,
// unknown keywords) are reported first; the semantic checks of validateProject() run only on a
// document that parsed cleanly, so one mistake gives one message.
[[nodiscard]] ProjectParseResult parseProjectJson(const QByteArray &json);

// The document for a project, indented, with keys in a stable order.
[[nodiscard]] QByteArray serializeProjectJson(const Project &project);

} // namespace tolturn
