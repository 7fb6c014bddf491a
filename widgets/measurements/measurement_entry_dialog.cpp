// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/measurements/measurement_entry_dialog.h"

#include "core/io/project_json.h"
#include "core/measurements/measurement_csv.h"

#include <QComboBox>
#include <QDateTimeEdit>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <functional>
#include <limits>
#include <set>

namespace tolturn {

namespace {

constexpr double kUmPerMm = 1000.0;

// A number as the user's locale writes it, or as C does ("12,5" and "12.5" in German); NaN
// otherwise, which validation then names.
double numberFrom(const QString &text)
{
    bool ok = false;
    const QString t = text.trimmed();
    double v = QLocale().toDouble(t, &ok);
    if (!ok)
        v = QLocale::c().toDouble(t, &ok);
    return ok ? v : std::numeric_limits<double>::quiet_NaN();
}

std::optional<double> optionalNumber(const QString &text)
{
    if (text.trimmed().isEmpty())
        return std::nullopt;
    return numberFrom(text);
}

QString numberText(double v)
{
    return QLocale().toString(v, 'g', 10);
}

} // namespace

MeasurementEntryDialog::MeasurementEntryDialog(const Project &project, const QString &measuredBy, QWidget *parent)
    : QDialog(parent)
    , m_project(project)
    , m_snapshot(serializeProjectJson(project))
    , m_measuredBy(new QLineEdit(measuredBy))
    , m_method(new QComboBox)
    , m_measuredAt(new QDateTimeEdit(QDateTime::currentDateTime()))
    , m_timeSinceStart(new QLineEdit)
    , m_ambient(new QLineEdit)
    , m_note(new QLineEdit)
    , m_table(new QTableWidget(0, ColumnCount))
    , m_problems(new QLabel)
{
    setObjectName(QStringLiteral("measurementEntryDialog"));
    setWindowTitle(tr("Measured Part — %1 on %2").arg(project.part.name, project.machineId));
    m_method->setEditable(true);
    m_method->addItems({tr("micrometer"), tr("CMM"), tr("bore gauge"), tr("dial gauge along the part")});
    m_measuredAt->setCalendarPopup(true);
    m_timeSinceStart->setPlaceholderText(tr("as in the project"));
    m_timeSinceStart->setToolTip(tr("Minutes from the machine's start to the cut: the warm-up the thermal error "
                                    "depends on (Li & Du 2022, §3.2)."));
    m_ambient->setPlaceholderText(tr("as in the project"));
    auto *form = new QFormLayout;
    form->addRow(tr("Measured &by:"), m_measuredBy);
    form->addRow(tr("&Method:"), m_method);
    form->addRow(tr("Measured &at:"), m_measuredAt);
    form->addRow(tr("&Time since start [min]:"), m_timeSinceStart);
    form->addRow(tr("Am&bient [°C]:"), m_ambient);
    form->addRow(tr("&Note:"), m_note);

    m_table->setHorizontalHeaderLabels({tr("Feature"), tr("z [mm]"), tr("Measured"), tr("Value")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setToolTip(tr("One measured point a row: a diameter in mm, or a radial deviation in µm (material "
                           "left on the surface positive)."));
    auto *add = new QPushButton(tr("Add &Row"));
    auto *remove = new QPushButton(tr("&Remove Rows"));
    auto *csv = new QPushButton(tr("Read &CSV…"));
    csv->setToolTip(tr("Columns feature, z_mm and diameter_mm or radial_deviation_um (docs/learning.md)."));
    connect(add, &QPushButton::clicked, this, &MeasurementEntryDialog::addRow);
    connect(remove, &QPushButton::clicked, this, &MeasurementEntryDialog::removeSelectedRows);
    connect(csv, &QPushButton::clicked, this, &MeasurementEntryDialog::chooseCsv);
    auto *rowButtons = new QHBoxLayout;
    rowButtons->addWidget(add);
    rowButtons->addWidget(remove);
    rowButtons->addWidget(csv);
    rowButtons->addStretch();

    m_problems->setObjectName(QStringLiteral("measurementProblems"));
    m_problems->setWordWrap(true);
    m_problems->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problems->setStyleSheet(QStringLiteral("color: #b00020;"));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Store"));
    connect(buttons, &QDialogButtonBox::accepted, this, &MeasurementEntryDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_table, 1);
    layout->addLayout(rowButtons);
    layout->addWidget(m_problems);
    layout->addWidget(buttons);
    resize(640, 560);
    addRow();
}

void MeasurementEntryDialog::addRow()
{
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    auto *feature = new QComboBox;
    for (const Contour *contour : {&m_project.part.outer, &m_project.part.inner}) {
        for (const Segment &s : contour->segments) {
            if (s.kind != SegmentKind::Face)
                feature->addItem(s.name.isEmpty() ? s.id : QStringLiteral("%1 — %2").arg(s.id, s.name), s.id);
        }
    }
    m_table->setCellWidget(row, Feature, feature);
    m_table->setItem(row, Z, new QTableWidgetItem);
    auto *quantity = new QComboBox;
    quantity->addItem(tr("diameter [mm]"), QVariant::fromValue(static_cast<int>(MeasuredQuantity::Diameter)));
    quantity->addItem(tr("radial deviation [µm]"),
                      QVariant::fromValue(static_cast<int>(MeasuredQuantity::RadialDeviation)));
    quantity->addItem(tr("CMM point x; y [mm]"), QVariant::fromValue(static_cast<int>(MeasuredQuantity::CmmPoint)));
    m_table->setCellWidget(row, Quantity, quantity);
    m_table->setItem(row, Value, new QTableWidgetItem);
}

int MeasurementEntryDialog::rowToFill()
{
    const int last = m_table->rowCount() - 1;
    if (last >= 0 && m_table->item(last, Z)->text().isEmpty() && m_table->item(last, Value)->text().isEmpty())
        return last;
    addRow();
    return m_table->rowCount() - 1;
}

void MeasurementEntryDialog::setFeature(int row, const QString &featureId)
{
    auto *feature = qobject_cast<QComboBox *>(m_table->cellWidget(row, Feature));
    if (feature->findData(featureId) < 0)
        feature->addItem(featureId, featureId); // not on the profile: kept, and named by validation
    feature->setCurrentIndex(feature->findData(featureId));
}

void MeasurementEntryDialog::addPoint(const QString &featureId, double z_mm, MeasuredQuantity quantity, double value)
{
    const int row = rowToFill();
    setFeature(row, featureId);
    m_table->item(row, Z)->setText(numberText(z_mm));
    auto *kind = qobject_cast<QComboBox *>(m_table->cellWidget(row, Quantity));
    kind->setCurrentIndex(kind->findData(static_cast<int>(quantity)));
    m_table->item(row, Value)->setText(numberText(value));
}

void MeasurementEntryDialog::addCmmPoint(const QString &featureId, double x_mm, double y_mm, double z_mm)
{
    addPoint(featureId, z_mm, MeasuredQuantity::CmmPoint, 0.0);
    m_table->item(m_table->rowCount() - 1, Value)->setText(numberText(x_mm) + QStringLiteral("; ") + numberText(y_mm));
}

void MeasurementEntryDialog::setPart(const MeasuredPart &part)
{
    const auto text = [](const std::optional<double> &v) { return v ? numberText(*v) : QString(); };
    m_measuredBy->setText(part.measuredBy);
    m_method->setCurrentText(part.method);
    if (part.measuredAt.isValid())
        m_measuredAt->setDateTime(part.measuredAt.toLocalTime());
    m_timeSinceStart->setText(text(part.timeSinceStart_min));
    m_ambient->setText(text(part.ambient_C));
    m_note->setText(part.note);
    m_table->setRowCount(0);
    addRow();
    for (const MeasuredPoint &p : part.points) {
        if (p.quantity == MeasuredQuantity::CmmPoint)
            addCmmPoint(p.featureId, p.x_mm, p.y_mm, p.z_mm);
        else
            addPoint(p.featureId, p.z_mm, p.quantity,
                     p.quantity == MeasuredQuantity::Diameter ? p.value_mm : p.value_mm * kUmPerMm);
    }
}

void MeasurementEntryDialog::removeSelectedRows()
{
    std::set<int, std::greater<>> rows; // from the last, so that the rows above keep their numbers
    for (const QModelIndex &index : m_table->selectionModel()->selectedIndexes())
        rows.insert(index.row());
    for (const int row : rows)
        m_table->removeRow(row);
    if (m_table->rowCount() == 0)
        addRow();
}

void MeasurementEntryDialog::chooseCsv()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Read Measured Points"), QString(),
                                                      tr("CSV files (*.csv *.txt);;All files (*)"));
    if (!path.isEmpty())
        readCsv(path);
}

bool MeasurementEntryDialog::readCsv(const QString &path)
{
    Diagnostics problems;
    const auto points = readMeasuredPoints(path, problems);
    if (!points) {
        QStringList lines;
        for (const Diagnostic &d : problems)
            lines << d.toString();
        m_problems->setText(tr("The file was not read:") + QLatin1Char('\n') + lines.join(QLatin1Char('\n')));
        return false;
    }
    MeasuredPart read = part();
    read.points = *points;
    setPart(read);
    m_problems->setText(
        tr("%n point(s) read from %1.", nullptr, static_cast<int>(points->size())).arg(QFileInfo(path).fileName()));
    return true;
}

MeasuredPart MeasurementEntryDialog::part() const
{
    MeasuredPart p;
    p.machineId = m_project.machineId;
    p.measuredAt = m_measuredAt->dateTime().toUTC();
    p.measuredBy = m_measuredBy->text().trimmed();
    p.method = m_method->currentText().trimmed();
    p.timeSinceStart_min = optionalNumber(m_timeSinceStart->text());
    p.ambient_C = optionalNumber(m_ambient->text());
    p.projectJson = m_snapshot;
    p.note = m_note->text().trimmed();
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QString z = m_table->item(row, Z)->text();
        const QString value = m_table->item(row, Value)->text();
        if (z.trimmed().isEmpty() && value.trimmed().isEmpty())
            continue; // an empty row is not a point
        const QString featureId =
            qobject_cast<QComboBox *>(m_table->cellWidget(row, Feature))->currentData().toString();
        const auto quantity = static_cast<MeasuredQuantity>(
            qobject_cast<QComboBox *>(m_table->cellWidget(row, Quantity))->currentData().toInt());
        MeasuredPoint point{featureId, numberFrom(z), quantity, numberFrom(value), 0.0, 0.0};
        if (quantity == MeasuredQuantity::RadialDeviation) {
            point.value_mm /= kUmPerMm;
        } else if (quantity == MeasuredQuantity::CmmPoint) {
            // "x; y" (or "x y"): a point that does not read gets NaNs, which validation names.
            static const QRegularExpression separator(QStringLiteral("\\s*[;\\s]\\s*"));
            const QStringList xy = value.trimmed().split(separator, Qt::SkipEmptyParts);
            const double nan = std::numeric_limits<double>::quiet_NaN();
            point = cmmPoint(featureId, xy.size() == 2 ? numberFrom(xy[0]) : nan,
                             xy.size() == 2 ? numberFrom(xy[1]) : nan, point.z_mm);
        }
        p.points.push_back(point);
    }
    return p;
}

// "points[3].z_mm" as the table shows it: "row 4, z". Only rows with a value count as points,
// so the point's index is mapped back to its row.
QString MeasurementEntryDialog::describeField(const QString &field) const
{
    static const QRegularExpression pointField(QStringLiteral(R"(^points\[(\d+)\]\.(\w+)$)"));
    const QRegularExpressionMatch m = pointField.match(field);
    if (!m.hasMatch())
        return field;
    int point = m.captured(1).toInt();
    int row = 0;
    for (; row < m_table->rowCount(); ++row) {
        const bool empty =
            m_table->item(row, Z)->text().trimmed().isEmpty() && m_table->item(row, Value)->text().trimmed().isEmpty();
        if (!empty && point-- == 0)
            break;
    }
    const QString column = m.captured(2);
    const QString name = column == QLatin1String("z_mm")      ? tr("z")
                         : column == QLatin1String("feature") ? tr("feature")
                                                              : tr("value");
    return tr("row %1, %2").arg(row + 1).arg(name);
}

QString MeasurementEntryDialog::problemsText() const
{
    return m_problems->text();
}

void MeasurementEntryDialog::accept()
{
    const Diagnostics problems = validateMeasuredPart(part());
    QStringList lines;
    for (const Diagnostic &d : problems) {
        if (d.severity == Severity::Error)
            lines << QStringLiteral("%1: %2").arg(describeField(d.field), d.message);
    }
    if (!lines.isEmpty()) {
        m_problems->setText(lines.join(QLatin1Char('\n')));
        return;
    }
    QDialog::accept();
}

} // namespace tolturn
