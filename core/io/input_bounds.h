// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QJsonObject>
#include <QString>

#include <vector>

namespace tolturn {

// The largest magnitude a number of a project file may have (docs/project-format.md, "Input
// bounds"). These are TolTurn's limits, not data about machines: wide enough for any turned part
// and any machine, narrow enough that no computation from them overflows a double.
struct InputBound {
    QString pattern; // a regular expression over the field, list indices written "[]"
                     // ("passes\\[\\]\\.feed_mm_rev" for the feed of every pass)
    double max;      // largest |value|
    QString unit;
};

// The bounds, most specific first; the last rule covers every number not named before it.
[[nodiscard]] const std::vector<InputBound> &inputBounds();

// An error per number of a project document beyond its bound, naming the field and the value.
void checkInputBounds(const QJsonObject &project, Diagnostics &out);

} // namespace tolturn
