// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/remedies.h"

#include "core/cutting/cutting_quantities.h"

#include <QCoreApplication>

namespace tolturn {

namespace {

struct Remedies {
    Q_DECLARE_TR_FUNCTIONS(Remedies)
};

QString number(double value)
{
    return QString::number(value, 'g', 3);
}

// Ra = f²/(32 r), Rz = f²/(8 r) (cutting_quantities.h) solved for the feed at the plan's nose
// radius, and for the nose radius at the least feed of the range when the feed falls below it.
QString roughness(const PlanningProblem &problem, const ConstraintValue &c)
{
    const bool ra = c.subject == QLatin1String("Ra");
    const double radius = problem.roughnessNoseRadius_mm();
    const double feed = ra ? feedForRa_mm_rev(c.limit, radius) : feedForRz_mm_rev(c.limit, radius);
    QString text = Remedies::tr("%1 ≤ %2 µm needs a feed of at most %3 mm/rev with the nose radius %4 mm (%5)")
                       .arg(c.subject, number(c.limit), number(feed), number(radius), problem.roughnessInsert());
    const double leastFeed = problem.feedRange().min;
    if (feed >= leastFeed)
        return text + QLatin1Char('.');
    const double needed = ra ? noseRadiusForRa_mm(c.limit, leastFeed) : noseRadiusForRz_mm(c.limit, leastFeed);
    return text + Remedies::tr(", below the feed range, which starts at %1 mm/rev; at that feed it needs a nose "
                               "radius of at least %2 mm.")
                      .arg(number(leastFeed), number(needed));
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
    QString text = Remedies::tr("A tool life of %1 min (%2) needs a cutting speed of at most %3 m/min (Taylor C = %4 "
                                "m/min, n = %5)")
                       .arg(number(life), c.subject, number(speed), number(*s.taylorC_m_min), number(*s.taylorN));
    const double leastSpeed = problem.speedRange().min;
    if (speed >= leastSpeed)
        return text + QLatin1Char('.');
    return text + Remedies::tr(", below the speed range, which starts at %1 m/min; at that speed it needs an insert "
                               "grade with C of at least %2 m/min.")
                      .arg(number(leastSpeed), number(taylorConstant_m_min(leastSpeed, life, *s.taylorN)));
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
