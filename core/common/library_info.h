// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <vector>

namespace tolturn {

// A third-party library TolTurn is built on, for Help > About and `tolturn-cli --version`.
struct LibraryInfo {
    QString name;
    QString version;
    QString licence;
};

[[nodiscard]] QString tolturnVersion();

// The libraries the core links: Qt (run-time version), OpenCascade, NLopt (run-time version),
// Eigen (headers). The widgets library adds QCustomPlot.
[[nodiscard]] std::vector<LibraryInfo> coreLibraries();

} // namespace tolturn
