// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/common/finding_groups.h"

#include <QRegularExpression>
#include <QStringList>

#include <algorithm>

namespace tolturn {

std::vector<FindingGroup> groupedByIndex(const Diagnostics &findings)
{
    static const QRegularExpression indexed(QStringLiteral("^(\\w+)\\[(\\d+)\\]\\.(.+)$"));
    std::vector<FindingGroup> groups;
    groups.reserve(findings.size());
    for (const Diagnostic &d : findings) {
        const QRegularExpressionMatch m = indexed.match(d.field);
        if (!m.hasMatch()) {
            groups.push_back({d, {}, {}, {}});
            continue;
        }
        const QString array = m.captured(1);
        const QString member = m.captured(3);
        const auto same = std::find_if(groups.begin(), groups.end(), [&](const FindingGroup &g) {
            return g.array == array && g.member == member && g.finding.severity == d.severity &&
                   g.finding.message == d.message;
        });
        if (same != groups.end())
            same->indices.push_back(m.captured(2).toInt());
        else
            groups.push_back({d, array, member, {m.captured(2).toInt()}});
    }
    return groups;
}

QString numberList(const std::vector<int> &numbers)
{
    const bool consecutive = numbers.size() > 2 &&
                             numbers.back() - numbers.front() + 1 == static_cast<int>(numbers.size()) &&
                             std::is_sorted(numbers.begin(), numbers.end());
    if (consecutive)
        return QStringLiteral("%1–%2").arg(numbers.front()).arg(numbers.back());
    QStringList list;
    for (const int n : numbers)
        list << QString::number(n);
    return list.join(QStringLiteral(", "));
}

QString groupText(const FindingGroup &group)
{
    if (group.indices.size() < 2)
        return group.finding.toString();
    Diagnostic d = group.finding;
    d.field = QStringLiteral("%1[%2].%3").arg(group.array, numberList(group.indices), group.member);
    return d.toString();
}

} // namespace tolturn
