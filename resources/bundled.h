// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

namespace tolturn {

// Example parts compiled into the programs, as Qt resource paths (":/examples/…"), by name.
[[nodiscard]] QStringList bundledExamplePaths();

// The application icon (SVG) as a Qt resource path.
[[nodiscard]] QString applicationIconPath();

} // namespace tolturn
