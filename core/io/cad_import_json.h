// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/cad/step_import.h"

#include <QJsonObject>
#include <QString>

#include <optional>

namespace tolturn {

// What `tolturn-cli import --json` prints of an import (docs/cli.md, import): the bodies and axes
// found, the ones chosen, the milled features made of flats and keyways (as the project file
// writes them), the findings. The profile itself goes to the project file. The desktop program
// reads it back from the import it runs in a child process (app/gui/cad_reader_process).
[[nodiscard]] QJsonObject cadImportJson(const CadImportResult &result);

// The bodies, axes, choices, milled features and findings of `json` (the profile is not in it);
// empty, with `error` set, when it is not such a document.
[[nodiscard]] std::optional<CadImportResult> cadImportResultFromJson(const QJsonObject &json, QString *error);

} // namespace tolturn
