// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/measurement_table.h"

#include <QCoreApplication>
#include <QFile>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

struct MeasurementFiles {
    Q_DECLARE_TR_FUNCTIONS(MeasurementFiles)
};

QString requiredNames(const std::vector<MeasurementColumn> &columns)
{
    QStringList names;
    for (const MeasurementColumn &c : columns)
        names << (c.required ? QLatin1String(c.name) : QStringLiteral("[%1]").arg(QLatin1String(c.name)));
    return names.join(QStringLiteral(", "));
}

// Where each column is in the header; errors for the required ones it lacks.
std::vector<qsizetype> headerColumns(const QStringList &cells, const QString &where,
                                     const std::vector<MeasurementColumn> &columns, Diagnostics &out)
{
    std::vector<qsizetype> columnOf;
    QStringList trimmed;
    for (const QString &cell : cells)
        trimmed << cell.trimmed();
    for (const MeasurementColumn &c : columns) {
        columnOf.push_back(trimmed.indexOf(QLatin1String(c.name)));
        // Twice named, either column could be meant: which one is read must not be a guess.
        if (const qsizetype again = trimmed.lastIndexOf(QLatin1String(c.name)); again != columnOf.back())
            out.push_back(makeError(where, MeasurementFiles::tr("the header names the column \"%1\" twice, as "
                                                                "columns %2 and %3")
                                               .arg(QLatin1String(c.name))
                                               .arg(columnOf.back() + 1)
                                               .arg(again + 1)));
        if (columnOf.back() < 0 && c.required)
            out.push_back(makeError(where, MeasurementFiles::tr("the header lacks the column \"%1\"; it needs %2")
                                               .arg(QLatin1String(c.name), requiredNames(columns))));
    }
    return columnOf;
}

MeasurementRow readRow(const QStringList &cells, const QString &where, const std::vector<MeasurementColumn> &columns,
                       const std::vector<qsizetype> &columnOf, Diagnostics &out, MeasurementTexts &texts)
{
    MeasurementRow row;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const QString cell = columnOf[c] < 0 ? QString() : cells.value(columnOf[c]).trimmed();
        if (columns[c].text) {
            if (cell.isEmpty() && columns[c].required)
                out.push_back(
                    makeError(where, MeasurementFiles::tr("%1 must not be empty").arg(QLatin1String(columns[c].name))));
            texts.cells << cell;
            row.emplace_back(std::nullopt);
            continue;
        }
        if (cell.isEmpty() && !columns[c].required) {
            row.emplace_back(std::nullopt);
            continue;
        }
        bool ok = false;
        const double v = cell.toDouble(&ok);
        if (!ok && cell.contains(QLatin1Char(','))) {
            out.push_back(makeError(where, MeasurementFiles::tr("%1 must be a number with a decimal point, not \"%2\"")
                                               .arg(QLatin1String(columns[c].name), cell)));
            row.emplace_back(std::nullopt);
            continue;
        }
        // No measured length, deviation, force, speed or time comes near 10⁹ in the columns' units
        // (mm, µm, N, rpm, min): such a value is a slip, and would overflow the fits downstream.
        constexpr double kLargestMeasurement = 1e9;
        if (ok && std::isfinite(v) && std::abs(v) > kLargestMeasurement)
            out.push_back(makeError(where, MeasurementFiles::tr("%1 must be at most 1e9 in size, not \"%2\"")
                                               .arg(QLatin1String(columns[c].name), cell)));
        else if (!ok || !std::isfinite(v) || (columns[c].positive && v <= 0.0))
            out.push_back(makeError(
                where, MeasurementFiles::tr("%1 must be a number%2, not \"%3\"")
                           .arg(QLatin1String(columns[c].name),
                                columns[c].positive ? MeasurementFiles::tr(" above zero") : QString(), cell)));
        row.emplace_back(v);
    }
    return row;
}

} // namespace

std::optional<std::vector<MeasurementRow>> parseMeasurementTable(const QString &text, const QString &fileName,
                                                                 const std::vector<MeasurementColumn> &columns,
                                                                 Diagnostics &out, std::vector<MeasurementTexts> *texts)
{
    // The header's separator is the file's: a semicolon file may write decimal commas ("49,992"),
    // which a comma split would cut into two cells and read as 49.
    QChar separator = QLatin1Char(',');
    qsizetype headerCells = 0;
    const int errorsBefore = countOf(out, Severity::Error);
    std::vector<qsizetype> columnOf;
    std::vector<MeasurementRow> rows;
    // Lines end in LF, CR LF or, from old Mac spreadsheets, CR alone: one file of one line otherwise.
    QString normalised = text;
    normalised.replace(QStringLiteral("\r\n"), QStringLiteral("\n")).replace(QLatin1Char('\r'), QLatin1Char('\n'));
    const QStringList lines = normalised.split(QLatin1Char('\n'));
    for (qsizetype n = 0; n < lines.size(); ++n) {
        const QString line = lines.at(n).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        const QString where = QStringLiteral("%1:%2").arg(fileName).arg(n + 1);
        if (columnOf.empty()) {
            if (line.contains(QLatin1Char(';')))
                separator = QLatin1Char(';');
            const QStringList cells = line.split(separator);
            headerCells = cells.size();
            columnOf = headerColumns(cells, where, columns, out);
            if (countOf(out, Severity::Error) > errorsBefore)
                return std::nullopt;
            continue;
        }
        const QStringList cells = line.split(separator);
        const bool beyondHeader = std::any_of(cells.begin() + std::min(headerCells, cells.size()), cells.end(),
                                              [](const QString &cell) { return !cell.trimmed().isEmpty(); });
        if (beyondHeader) {
            out.push_back(makeError(where, MeasurementFiles::tr("the line has %1 cells, the header %2: \"%3\"")
                                               .arg(cells.size())
                                               .arg(headerCells)
                                               .arg(line)));
            continue;
        }
        MeasurementTexts rowTexts{static_cast<int>(n + 1), {}};
        rows.push_back(readRow(cells, where, columns, columnOf, out, rowTexts));
        if (texts)
            texts->push_back(rowTexts);
    }
    if (columnOf.empty())
        out.push_back(makeError(fileName, MeasurementFiles::tr("the file has no header line")));
    else if (rows.empty())
        out.push_back(makeError(fileName, MeasurementFiles::tr("the file has no measurement")));
    if (countOf(out, Severity::Error) > errorsBefore)
        return std::nullopt;
    return rows;
}

std::optional<std::vector<MeasurementRow>> readMeasurementTable(const QString &path,
                                                                const std::vector<MeasurementColumn> &columns,
                                                                Diagnostics &out, std::vector<MeasurementTexts> *texts)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        out.push_back(makeError(QStringLiteral("file"),
                                MeasurementFiles::tr("cannot open '%1': %2").arg(path, file.errorString())));
        return std::nullopt;
    }
    return parseMeasurementTable(QString::fromUtf8(file.readAll()), path, columns, out, texts);
}

} // namespace tolturn
