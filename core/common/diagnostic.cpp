// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/common/diagnostic.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace tolturn {

QString Diagnostic::toString() const
{
    const QString prefix = severity == Severity::Error ? QStringLiteral("error") : QStringLiteral("warning");
    if (field.isEmpty())
        return prefix + QStringLiteral(": ") + message;
    return prefix + QStringLiteral(": ") + field + QStringLiteral(": ") + message;
}

QJsonObject diagnosticJson(const Diagnostic &d)
{
    return {{QStringLiteral("severity"),
             d.severity == Severity::Error ? QStringLiteral("error") : QStringLiteral("warning")},
            {QStringLiteral("field"), d.field},
            {QStringLiteral("message"), d.message}};
}

Diagnostic diagnosticFromJson(const QJsonObject &o)
{
    const bool warning = o.value(QStringLiteral("severity")).toString() == QLatin1String("warning");
    return {warning ? Severity::Warning : Severity::Error, o.value(QStringLiteral("field")).toString(),
            o.value(QStringLiteral("message")).toString()};
}

bool hasErrors(const Diagnostics &diagnostics)
{
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic &d) { return d.severity == Severity::Error; });
}

int countOf(const Diagnostics &diagnostics, Severity severity)
{
    return static_cast<int>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                          [severity](const Diagnostic &d) { return d.severity == severity; }));
}

Diagnostic makeError(const QString &field, const QString &message)
{
    return Diagnostic{Severity::Error, field, message};
}

Diagnostic makeWarning(const QString &field, const QString &message)
{
    return Diagnostic{Severity::Warning, field, message};
}

QString formatNumber(double value)
{
    return QString::number(value, 'g', 10);
}

QString formatFixed(double value, int decimals)
{
    return std::abs(value) < 1e9 ? QString::number(value, 'f', decimals) : QString::number(value, 'g', 4);
}

QString spanText(const QString &low, const QString &high)
{
    return low == high ? low : low + QStringLiteral("–") + high;
}

QString formatNumberExactly(double value)
{
    // Ten digits where they hold the number (1000000000, 0.0004), else every digit it needs.
    if (QString tenDigits = formatNumber(value); tenDigits.toDouble() == value)
        return tenDigits;
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

} // namespace tolturn
