// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/measurements/measured_part.h"
#include "core/project/project.h"

#include <QDialog>

class QComboBox;
class QDateTimeEdit;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace tolturn {

// A measured part typed in (docs/learning.md): who measured it and how, the shop conditions of
// the cut, and its points in a table, one per row (feature, z, diameter or radial deviation); a
// CSV file can fill the table. The part keeps the open project as the snapshot it was cut from.
// OK checks the part as the store will (validateMeasuredPart) and names each problem by its row
// and column; the dialog stays open with everything typed until it is right.
class MeasurementEntryDialog : public QDialog {
    Q_OBJECT
public:
    enum Column { Feature, Z, Quantity, Value, ColumnCount };

    MeasurementEntryDialog(const Project &project, const QString &measuredBy, QWidget *parent = nullptr);

    // The part as typed, with the project's snapshot and machine; a cell that is not a number
    // makes a NaN that validation names.
    [[nodiscard]] MeasuredPart part() const;

    // Fills the table from a CSV file (measurement_csv.h); false, with the problems shown and the
    // table unchanged, when the file has any.
    bool readCsv(const QString &path);
    // Appends a row (a feature id of the snapshot, z in mm, the value in mm for a diameter or in
    // µm for a radial deviation, as the table shows it).
    void addPoint(const QString &featureId, double z_mm, MeasuredQuantity quantity, double value);
    // Appends a CMM point: its x and y (mm, across the axis) in the value cell, "x; y".
    void addCmmPoint(const QString &featureId, double x_mm, double y_mm, double z_mm);
    // Fills the dialog with a part typed before (its snapshot stays the dialog's project).
    void setPart(const MeasuredPart &part);

    [[nodiscard]] QTableWidget *table() const { return m_table; }

    [[nodiscard]] QString problemsText() const;

    void accept() override;

private:
    void addRow();
    // The row to fill: the last when it is empty, else a new one.
    [[nodiscard]] int rowToFill();
    void setFeature(int row, const QString &featureId);
    void removeSelectedRows();
    void chooseCsv();
    [[nodiscard]] QString describeField(const QString &field) const;

    Project m_project;
    QByteArray m_snapshot;
    QLineEdit *m_measuredBy;
    QComboBox *m_method;
    QDateTimeEdit *m_measuredAt;
    QLineEdit *m_timeSinceStart;
    QLineEdit *m_ambient;
    QLineEdit *m_note;
    QTableWidget *m_table;
    QLabel *m_problems;
};

} // namespace tolturn
