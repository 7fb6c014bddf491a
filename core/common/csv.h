// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

namespace tolturn {

// One field of a CSV line (RFC 4180 §2.6–2.7): quoted when it holds a comma, a quote or a line
// break, with its quotes doubled.
[[nodiscard]] QString csvField(const QString &text);

// Fields joined into one CSV line.
[[nodiscard]] QString csvLine(const QStringList &fields);

} // namespace tolturn
