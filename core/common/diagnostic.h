// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QJsonObject>
#include <QString>

#include <vector>

namespace tolturn {

enum class Severity { Warning, Error };

// One finding about an input: which field (a JSON-style path such as
// "part.outer[2].to.r_mm") and a full sentence that names the value.
struct Diagnostic {
    Severity severity = Severity::Error;
    QString field;
    QString message;

    // "field: message", the form printed by the CLI and shown in dialogs.
    [[nodiscard]] QString toString() const;

    friend bool operator==(const Diagnostic &, const Diagnostic &) = default;
};

using Diagnostics = std::vector<Diagnostic>;

[[nodiscard]] bool hasErrors(const Diagnostics &diagnostics);
[[nodiscard]] int countOf(const Diagnostics &diagnostics, Severity severity);
[[nodiscard]] Diagnostic makeError(const QString &field, const QString &message);
[[nodiscard]] Diagnostic makeWarning(const QString &field, const QString &message);

// A finding as JSON: {"severity": "error" | "warning", "field": …, "message": …}, the form of
// every command's --json output; and back (a missing or unknown severity reads as an error).
[[nodiscard]] QJsonObject diagnosticJson(const Diagnostic &d);
[[nodiscard]] Diagnostic diagnosticFromJson(const QJsonObject &o);

// Number formatting for messages: shortest form that round-trips to the shown precision.
[[nodiscard]] QString formatNumber(double value);
// A number as a file has it, to the last digit that tells it apart (5000.0000001 is not 5000):
// for messages about values a user wrote, and for limits compared with them.
[[nodiscard]] QString formatNumberExactly(double value);
// An amount to `decimals` places, or to four significant digits once it is too large for a row of
// digits to be read (degenerate tool-life data make the time per part 10^260 min).
[[nodiscard]] QString formatFixed(double value, int decimals);
// A range as shown, "2334–2335", or one value where both ends read the same ("49.994", not
// "49.994–49.994").
[[nodiscard]] QString spanText(const QString &low, const QString &high);

} // namespace tolturn
