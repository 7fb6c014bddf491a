// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/library_info.h"

#include <QDialog>

namespace tolturn {

// Every library the programs are built on: the core's plus QCustomPlot (plots).
[[nodiscard]] std::vector<LibraryInfo> applicationLibraries();

// Help > About: program version and licence, and each library with its version and licence.
class AboutDialog : public QDialog {
    Q_OBJECT
public:
    explicit AboutDialog(QWidget *parent = nullptr);

    [[nodiscard]] static QString aboutHtml();
};

} // namespace tolturn
