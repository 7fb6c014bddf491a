// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/remedies.h"

#include "core/cutting/cutting_quantities.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

struct Remedies {
    Q_DECLARE_TR_FUNCTIONS(Remedies)
};

// A value given in the data, as it is.
QString given(double value)
{
    return QString::number(value, 'g', 6);
}

// A limit worked out from them, to three significant figures in plain decimals and on the safe
// side: an upper limit rounded down, a lower one up (176.78 m/min "at most 176", 0.5645 mm
// "at least 0.565").
QString rounded(double value, bool up)
{
    if (!std::isfinite(value) || value < 1e-6) // out of any machining range: as it is
        return given(value);
    const int decimals = std::clamp(2 - static_cast<int>(std::floor(std::log10(value))), 0, 8);
    const double scale = std::pow(10.0, decimals);
    const double r = (up ? std::ceil(value * scale - 1e-9) : std::floor(value * scale + 1e-9)) / scale;
    return QString::number(r, 'f', decimals);
}

QString atMost(double value)
{
    return rounded(value, false);
}

QString atLeast(double value)
{
    return rounded(value, true);
}

// "CNMG 120404 (0.4 mm); CCMT 09T304, the boring bar's insert (0.4 mm)": the inserts with a nose
// radius below `radius_mm`, or (`equal`) with the smallest.
QString insertsBelow(const PlanningProblem &problem, double radius_mm, bool equal)
{
    QStringList names;
    for (const PlanningProblem::RoughnessInsert &i : problem.roughnessInserts()) {
        const bool named = equal ? i.noseRadius_mm <= radius_mm + 1e-12 : i.noseRadius_mm < radius_mm;
        if (named)
            names << Remedies::tr("%1 (%2 mm)").arg(i.insert, given(i.noseRadius_mm));
    }
    return names.join(QStringLiteral("; "));
}

// Ra = f²/(32 r), Rz = f²/(8 r) (cutting_quantities.h) solved for the feed at the smallest nose
// radius, and for the nose radius at the least feed of the range when the feed falls below it.
QString roughness(const PlanningProblem &problem, const ConstraintValue &c)
{
    const bool ra = c.subject == QLatin1String("Ra");
    const double radius = problem.roughnessNoseRadius_mm();
    const double feed = ra ? feedForRa_mm_rev(c.limit, radius) : feedForRz_mm_rev(c.limit, radius);
    QString text = Remedies::tr("%1 ≤ %2 µm needs a feed of at most %3 mm/rev with the nose radius of %4")
                       .arg(c.subject, given(c.limit), atMost(feed), insertsBelow(problem, radius, true));
    const double leastFeed = problem.feedRange().min;
    if (feed >= leastFeed)
        return text + QLatin1Char('.');
    const double needed = ra ? noseRadiusForRa_mm(c.limit, leastFeed) : noseRadiusForRz_mm(c.limit, leastFeed);
    return text + Remedies::tr(", below the feed range, which starts at %1 mm/rev; at that feed it needs a nose "
                               "radius of at least %2 mm on %3.")
                      .arg(given(leastFeed), atLeast(needed), insertsBelow(problem, needed, false));
}

// Taylor, v T^n = C: the highest speed that gives the least tool life, and, when that is below
// the speed range, the C an insert grade would need to give it at the range's lowest speed.
QString toolLife(const PlanningProblem &problem, const ConstraintValue &c)
{
    const PlanningSettings &s = problem.project().planning;
    if (!s.taylorC_m_min || !s.taylorN)
        return {};
    const double life = c.value; // written T_min <= T
    const double speed = speedForToolLife_m_min(*s.taylorC_m_min, life, *s.taylorN);
    QString text = Remedies::tr("A tool life of %1 min needs a cutting speed of at most %2 m/min (Taylor C = %3 "
                                "m/min, n = %4)")
                       .arg(given(life), atMost(speed), given(*s.taylorC_m_min), given(*s.taylorN));
    const double leastSpeed = problem.speedRange().min;
    if (speed >= leastSpeed)
        return text + QLatin1Char('.');
    return text + Remedies::tr(", below the speed range, which starts at %1 m/min; at that speed it needs an insert "
                               "grade with C of at least %2 m/min.")
                      .arg(given(leastSpeed), atLeast(taylorConstant_m_min(leastSpeed, life, *s.taylorN)));
}

} // namespace

QString whatItWouldTake(const PlanningProblem &problem, const ConstraintValue &violated)
{
    if (violated.name == QLatin1String("roughness"))
        return roughness(problem, violated);
    if (violated.name == QLatin1String("tool_life"))
        return toolLife(problem, violated);
    return {};
}

} // namespace tolturn
