// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/pass_time.h"

#include "core/planning/path_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tolturn {

std::vector<FeedStep> feedSteps(const PassPath &pass)
{
    std::vector<FeedStep> steps;
    std::optional<ProfilePoint> at;
    for (const ToolMove &m : pass.moves) {
        if (m.kind != MoveKind::Rapid && at) {
            PathElement e;
            e.from = *at;
            e.to = m.to;
            e.arc = m.kind != MoveKind::Feed;
            e.centre = m.centre;
            e.radius_mm = m.radius_mm;
            e.counterClockwise = m.kind == MoveKind::ArcCounterClockwise;
            const std::vector<ProfilePoint> points = sampled(e, 0.05, 2000);
            for (std::size_t i = 1; i < points.size(); ++i)
                steps.push_back({points[i - 1], points[i], m.feed_mm_rev});
        }
        at = m.to;
    }
    return steps;
}

double g96SpindleSpeed_rpm(double cuttingSpeed_m_min, double r_mm, double limit_rpm)
{
    if (r_mm <= 1e-9)
        return limit_rpm;
    return std::min(limit_rpm, 1000.0 * cuttingSpeed_m_min / (2.0 * std::numbers::pi * r_mm));
}

double feedTime_min(const std::vector<FeedStep> &steps, double cuttingSpeed_m_min, double feed_mm_rev, double limit_rpm)
{
    double time = 0.0;
    for (const FeedStep &s : steps) {
        const double length = std::hypot(s.to.z_mm - s.from.z_mm, s.to.r_mm - s.from.r_mm);
        const double r = 0.5 * (s.to.r_mm + s.from.r_mm);
        time += length / (s.feed_mm_rev.value_or(feed_mm_rev) * g96SpindleSpeed_rpm(cuttingSpeed_m_min, r, limit_rpm));
    }
    return time;
}

FeedTimeTable::FeedTimeTable(const std::vector<FeedStep> &steps)
{
    std::vector<std::pair<double, double>> byRadius; // (middle radius, length)
    byRadius.reserve(steps.size());
    for (const FeedStep &s : steps)
        byRadius.emplace_back(0.5 * (s.to.r_mm + s.from.r_mm),
                              std::hypot(s.to.z_mm - s.from.z_mm, s.to.r_mm - s.from.r_mm));
    std::sort(byRadius.begin(), byRadius.end());
    const std::size_t n = byRadius.size();
    m_radius_mm.resize(n);
    m_lengthUpTo.assign(n + 1, 0.0);
    m_momentFrom.assign(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        m_radius_mm[i] = byRadius[i].first;
        m_lengthUpTo[i + 1] = m_lengthUpTo[i] + byRadius[i].second;
    }
    for (std::size_t i = n; i-- > 0;)
        m_momentFrom[i] = m_momentFrom[i + 1] + byRadius[i].second * byRadius[i].first;
}

double FeedTimeTable::time_min(double cuttingSpeed_m_min, double feed_mm_rev, double limit_rpm) const
{
    if (m_radius_mm.empty())
        return 0.0; // no feed move: no time, as feedTime_min
    // n = min(limit, 1000 v / (2 pi r)), and the limit on r <= 1e-9 (g96SpindleSpeed_rpm): the
    // first step at G96 is the first whose radius is above both.
    const double perRadius = 1000.0 * cuttingSpeed_m_min / (2.0 * std::numbers::pi); // n r [rpm mm]
    const double rc = std::max(perRadius / limit_rpm, 1e-9);
    const auto first =
        static_cast<std::size_t>(std::upper_bound(m_radius_mm.begin(), m_radius_mm.end(), rc) - m_radius_mm.begin());
    // A step exactly on r_c runs at the limit either way: n = limit there.
    const double atLimit = std::isfinite(limit_rpm) ? m_lengthUpTo[first] / limit_rpm : 0.0;
    return (atLimit + m_momentFrom[first] / perRadius) / feed_mm_rev;
}

} // namespace tolturn
