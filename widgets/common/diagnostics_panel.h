// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace tolturn {

// A list of findings (errors and warnings, each with its field and message) under a heading,
// e.g. what a STEP import left out of the profile. Copies as CSV; activating a row (double click,
// Enter) names its field.
class DiagnosticsPanel : public QWidget {
    Q_OBJECT
public:
    explicit DiagnosticsPanel(QWidget *parent = nullptr);

    void showDiagnostics(const QString &heading, const Diagnostics &diagnostics);

    [[nodiscard]] QTableWidget *table() const { return m_table; }

    [[nodiscard]] QString heading() const;

Q_SIGNALS:
    void fieldActivated(const QString &field);

private:
    QLabel *m_heading;
    QTableWidget *m_table;
};

} // namespace tolturn
