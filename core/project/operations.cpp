// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/operations.h"

#include "core/part/profile_geometry.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <set>

namespace tolturn {

namespace {

struct Operations {
    Q_DECLARE_TR_FUNCTIONS(Operations)
};

QStringList allFeatureIds(const PartProfile &part)
{
    QStringList ids;
    for (const Contour *c : {&part.outer, &part.inner}) {
        for (const Segment &s : c->segments)
            ids << s.id;
    }
    return ids;
}

Contour mirrored(const Contour &contour, double length_mm)
{
    Contour out;
    out.segments.reserve(contour.segments.size());
    for (std::size_t i = contour.segments.size(); i-- > 0;) { // clang 14 cannot use views::reverse
        const Segment &original = contour.segments[i];
        // Mirroring z reverses an arc's sense, and so does travelling it backwards: its direction
        // as stored stays the same.
        Segment s = original;
        s.from = {length_mm - original.to.z_mm, original.to.r_mm};
        s.to = {length_mm - original.from.z_mm, original.from.r_mm};
        out.segments.push_back(s);
    }
    return out;
}

// The z ranges (in the operation's frame) of a contour's turned or bored features that later
// operations cut: there the part still has its stock outside, its solid material inside.
std::vector<std::pair<double, double>> laterRanges(const Project &project, const Contour &held, int index)
{
    std::vector<std::pair<double, double>> ranges;
    for (const Segment &s : held.segments) {
        if (!s.isAxial() || operationOf(project, s.id) <= index)
            continue;
        const double a = std::min(s.from.z_mm, s.to.z_mm);
        const double b = std::max(s.from.z_mm, s.to.z_mm);
        if (!ranges.empty() && a <= ranges.back().second + kProfileEpsilon_mm)
            ranges.back().second = std::max(ranges.back().second, b);
        else
            ranges.emplace_back(a, b);
    }
    return ranges;
}

// A tolerance is judged in the set-up that cuts its feature (a length: its first face).
bool judgedIn(const QStringList &cut, const Tolerance &t)
{
    return cut.contains(t.featureId);
}

} // namespace

int operationCount(const Project &project)
{
    return 1 + static_cast<int>(project.furtherOperations.size());
}

QString operationName(const Project &project, int index)
{
    const QString given = index == 0 ? project.firstOperationName
                                     : project.furtherOperations.at(static_cast<std::size_t>(index - 1)).name;
    return given.isEmpty() ? QStringLiteral("OP %1").arg(10 * (index + 1)) : given;
}

const Clamping &operationClamping(const Project &project, int index)
{
    return index == 0 ? project.clamping : project.furtherOperations.at(static_cast<std::size_t>(index - 1)).clamping;
}

QStringList operationFeatures(const Project &project, int index)
{
    if (index > 0)
        return project.furtherOperations.at(static_cast<std::size_t>(index - 1)).features;
    QStringList ids;
    for (const QString &id : allFeatureIds(project.part)) {
        if (operationOf(project, id) == 0)
            ids << id;
    }
    return ids;
}

int operationOf(const Project &project, const QString &featureId)
{
    for (std::size_t i = 0; i < project.furtherOperations.size(); ++i) {
        if (project.furtherOperations[i].features.contains(featureId))
            return static_cast<int>(i) + 1;
    }
    return 0;
}

PartProfile partAsHeld(const PartProfile &part, PartEnd heldEnd)
{
    if (heldEnd == PartEnd::Left)
        return part;
    PartProfile out = part;
    const double length = part.length_mm();
    out.outer = mirrored(part.outer, length);
    out.inner = mirrored(part.inner, length);
    return out;
}

Project operationView(const Project &project, int index)
{
    if (project.scope || (operationCount(project) == 1 && project.clamping.heldEnd == PartEnd::Left))
        return project; // a view already, or the project as drawn and held
    Project view = project;
    if (index > 0) {
        const Operation &op = project.furtherOperations.at(static_cast<std::size_t>(index - 1));
        view.clamping = op.clamping;
        view.tool = op.tool;
        view.boringTool = op.boringTool;
        view.passes = op.passes;
    }
    view.firstOperationName = operationName(project, index);
    view.furtherOperations.clear();
    view.part = partAsHeld(project.part, view.clamping.heldEnd);
    OperationScope scope;
    scope.name = view.firstOperationName;
    scope.index = index;
    scope.count = operationCount(project);
    scope.cutFeatures = operationFeatures(project, index);
    for (const QString &id : allFeatureIds(project.part)) {
        if (const int op = operationOf(project, id); op != index)
            scope.cutElsewhere.insert(id, operationName(project, op));
    }
    scope.stockOuter_mm = laterRanges(project, view.part.outer, index);
    scope.solidInner_mm = laterRanges(project, view.part.inner, index);
    view.tolerances.clear();
    for (const Tolerance &t : project.tolerances) {
        if (judgedIn(scope.cutFeatures, t))
            view.tolerances.push_back(t);
    }
    view.scope = scope;
    return view;
}

bool cutsBores(const Project &project)
{
    return std::any_of(project.part.inner.segments.begin(), project.part.inner.segments.end(), [&](const Segment &s) {
        return project.scope ? project.scope->cutFeatures.contains(s.id) : operationOf(project, s.id) == 0;
    });
}

bool spansOperations(const Project &project, const Tolerance &tolerance)
{
    if (project.scope) { // the view of one operation: what it does not cut, another operation does
        const QStringList &cut = project.scope->cutFeatures;
        if (!tolerance.toFeatureId.isEmpty() && !cut.contains(tolerance.toFeatureId))
            return true;
        return std::any_of(tolerance.datums.begin(), tolerance.datums.end(), [&](const QString &label) {
            return std::any_of(project.datums.begin(), project.datums.end(),
                               [&](const Datum &d) { return d.label == label && !cut.contains(d.featureId); });
        });
    }
    const int own = operationOf(project, tolerance.featureId);
    if (!tolerance.toFeatureId.isEmpty() && operationOf(project, tolerance.toFeatureId) != own)
        return true;
    return std::any_of(tolerance.datums.begin(), tolerance.datums.end(), [&](const QString &label) {
        return std::any_of(project.datums.begin(), project.datums.end(), [&](const Datum &d) {
            return d.label == label && operationOf(project, d.featureId) != own;
        });
    });
}

std::optional<ReclampingError> reclampingError(const Project &project, const Tolerance &tolerance,
                                               const DataLibrary &data)
{
    if (!spansOperations(project, tolerance))
        return std::nullopt;
    std::optional<SourcedValue> value;
    switch (tolerance.type) {
    case ToleranceType::Coaxiality:
    case ToleranceType::CircularRadialRunout:
    case ToleranceType::TotalRadialRunout:
        value = data.reclamping().concentricity_mm;
        break;
    case ToleranceType::Perpendicularity:
    case ToleranceType::Parallelism:
    case ToleranceType::CircularAxialRunout:
    case ToleranceType::TotalAxialRunout:
        value = data.reclamping().axialRunout_mm;
        break;
    default:
        return std::nullopt; // sizes and forms do not depend on where the part was clamped before
    }
    if (!value)
        return std::nullopt;
    return ReclampingError{1000.0 * value->value, data.sourceText(value->source).section(QLatin1Char(','), 0, 1)};
}

namespace {

// Whether a feature is cut in another set-up than the toleranced one, and that set-up's name
// (a view knows only that it is another).
std::optional<QString> otherSetUp(const Project &project, const QString &featureId, const QString &tolerancedId)
{
    if (project.scope) {
        if (project.scope->cutFeatures.contains(featureId))
            return std::nullopt;
        return project.scope->cutElsewhere.value(featureId, Operations::tr("another set-up"));
    }
    const int op = operationOf(project, featureId);
    if (op == operationOf(project, tolerancedId))
        return std::nullopt;
    return operationName(project, op);
}

} // namespace

QString reclampingText(const Project &project, const Tolerance &tolerance, const ReclampingError &error,
                       std::optional<double> value_um, std::optional<double> limit_um)
{
    QStringList others;
    for (const QString &label : tolerance.datums) {
        for (const Datum &d : project.datums) {
            if (d.label != label)
                continue;
            if (const auto where = otherSetUp(project, d.featureId, tolerance.featureId))
                others << Operations::tr("datum %1 on %2 is cut in %3").arg(label, d.featureId, *where);
        }
    }
    if (!tolerance.toFeatureId.isEmpty()) {
        if (const auto where = otherSetUp(project, tolerance.toFeatureId, tolerance.featureId))
            others << Operations::tr("%1 is cut in %2").arg(tolerance.toFeatureId, *where);
    }
    const QString own =
        project.scope ? project.scope->name : operationName(project, operationOf(project, tolerance.featureId));
    QString text =
        Operations::tr("spans set-ups: %1, %2 in %3; clamping again adds 0–%4 µm (%5)")
            .arg(others.join(QStringLiteral("; ")), tolerance.featureId, own, formatNumber(error.max_um), error.source);
    const Clamping &held =
        project.scope ? project.clamping : operationClamping(project, operationOf(project, tolerance.featureId));
    if (held.method == ClampingMethod::Collet)
        text += Operations::tr(", a chuck's figure: no collet maker's is in the data");
    if (value_um && limit_um) {
        const double room = *limit_um - *value_um;
        text += room >= error.max_um
                    ? Operations::tr("; it holds with the largest of it")
                    : (room > 0.0 ? Operations::tr("; it holds only if the re-clamping error stays below %1 µm")
                                        .arg(QString::number(room, 'f', 1))
                                  : Operations::tr("; it fails even without it"));
    }
    return text;
}

namespace {

// A feature the operation that cuts it cannot reach. The first operation cuts what no other names:
// a feature left to it by default is a warning (on its clamping's field), one an operation names
// itself an error (on its feature list).
void sayUnreachable(int index, const QString &firstOperationField, const QString &message, Diagnostics &out)
{
    if (index == 0)
        out.push_back(makeWarning(firstOperationField, message));
    else
        out.push_back(makeError(QStringLiteral("further_operations[%1].features").arg(index - 1), message));
}

// A blind bore that opens at the end the chuck holds is closed to the tool: the jaws and the
// chuck are in its mouth.
void checkBoreReach(const Project &project, int index, const PartProfile &held, const QStringList &cut,
                    Diagnostics &out)
{
    const std::vector<Segment> &s = held.inner.segments;
    for (const auto &[start, end] : held.inner.pieces()) {
        const bool opensAtHeldEnd = s[start].from.z_mm <= kProfileEpsilon_mm;
        const bool blind = s[end - 1].to.z_mm < held.length_mm() - kProfileEpsilon_mm;
        for (std::size_t j = start; j < end && opensAtHeldEnd && blind; ++j) {
            if (cut.contains(s[j].id))
                sayUnreachable(index, QStringLiteral("clamping.held_end"),
                               Operations::tr("feature %1 is in the bore that opens at the end %2 holds: no tool "
                                              "reaches it there; name it in an operation that holds the other end")
                                   .arg(s[j].id, operationName(project, index)),
                               out);
        }
    }
}

// A feature that lies wholly inside the jaws of the operation that cuts it cannot be reached there.
void checkReach(const Project &project, int index, Diagnostics &out)
{
    const Clamping &c = operationClamping(project, index);
    if (c.method == ClampingMethod::BetweenCentres || c.clampedLength_mm <= 0.0)
        return;
    const PartProfile held = partAsHeld(project.part, c.heldEnd);
    const QStringList cut = operationFeatures(project, index);
    for (const Segment &s : held.outer.segments) {
        if (!cut.contains(s.id) || std::max(s.from.z_mm, s.to.z_mm) > c.clampedLength_mm + kProfileEpsilon_mm)
            continue;
        sayUnreachable(index, QStringLiteral("clamping.clamped_length_mm"),
                       Operations::tr("feature %1 lies in the jaws of %2 (%3 mm from its held end): no tool reaches "
                                      "it there; name it in an operation that holds the other end")
                           .arg(s.id, operationName(project, index), formatNumber(c.clampedLength_mm)),
                       out);
    }
    checkBoreReach(project, index, held, cut, out);
}

} // namespace

std::optional<SplitProposal> proposeSplit(const Project &project, QString *why)
{
    const auto say = [why](const QString &text) {
        if (why != nullptr)
            *why = text;
        return std::nullopt;
    };
    const Clamping &first = project.clamping;
    if (operationCount(project) > 1 || first.method == ClampingMethod::BetweenCentres || first.clampedLength_mm <= 0.0)
        return say(Operations::tr("the part is not held in a chuck in one set-up"));
    const PartProfile held = partAsHeld(project.part, first.heldEnd);
    const double length = held.length_mm();
    QStringList inJaws;
    for (const Segment &s : held.outer.segments) {
        if (std::min(s.from.z_mm, s.to.z_mm) < first.clampedLength_mm - kProfileEpsilon_mm)
            inJaws << s.id;
    }
    if (inJaws.isEmpty())
        return say(Operations::tr("no feature lies in the jaws"));
    // The grip of the second set-up: the outer cylinder nearest the free end of the first.
    const auto &outer = held.outer.segments;
    const auto grip = std::find_if(outer.rbegin(), outer.rend(), [&inJaws](const Segment &s) {
        return s.kind == SegmentKind::Cylinder && !inJaws.contains(s.id); // finished in the first set-up
    });
    if (grip == outer.rend())
        return say(Operations::tr("there is no outer cylinder to hold the part by at its other end"));
    // The grip lies right of every feature the first set-up's jaws cover, so the second set-up's
    // jaws leave them free.
    const double gripLength = proposedGripLength_mm(grip->to.z_mm - grip->from.z_mm, length);
    SplitProposal proposal;
    Operation &op = proposal.second;
    op.name = QStringLiteral("OP 20");
    op.clamping = first;
    op.clamping.heldEnd = first.heldEnd == PartEnd::Left ? PartEnd::Right : PartEnd::Left;
    op.clamping.clampedLength_mm = gripLength;
    op.tool = project.tool;
    op.boringTool = project.boringTool;
    op.passes = project.passes;
    op.features = inJaws;
    proposal.reason =
        Operations::tr("the jaws of %2 (%3 mm) cover %1: turn the part end for end and hold it %4 mm on "
                       "%5 Ø%6, finished in %2, to turn them in %7")
            .arg(inJaws.join(QStringLiteral(", ")), operationName(project, 0), formatNumber(first.clampedLength_mm),
                 formatNumber(gripLength), grip->id, formatNumber(2.0 * grip->to.r_mm), op.name);
    return proposal;
}

double proposedGripLength_mm(double available_mm, double partLength_mm)
{
    return std::floor(10.0 * std::min(available_mm, partLength_mm / 3.0) + 1e-9) / 10.0;
}

Diagnostics checkOperations(const Project &project)
{
    Diagnostics out;
    if (project.furtherOperations.empty())
        return out;
    const QStringList ids = allFeatureIds(project.part);
    std::set<QString> names{operationName(project, 0)};
    std::set<QString> named;
    for (std::size_t i = 0; i < project.furtherOperations.size(); ++i) {
        const Operation &op = project.furtherOperations[i];
        const QString path = QStringLiteral("further_operations[%1]").arg(i);
        if (op.name.trimmed().isEmpty())
            out.push_back(makeError(path + QStringLiteral(".name"), Operations::tr("an operation needs a name")));
        else if (!names.insert(op.name).second)
            out.push_back(makeError(path + QStringLiteral(".name"),
                                    Operations::tr("two operations are named \"%1\"").arg(op.name)));
        // An operation without passes is check's to refuse (checkPlausibility), as the first one's
        // is: the optimiser plans the passes of a set-up that has none yet.
        if (op.features.isEmpty())
            out.push_back(makeError(path + QStringLiteral(".features"),
                                    Operations::tr("operation \"%1\" cuts no feature").arg(op.name)));
        for (qsizetype j = 0; j < op.features.size(); ++j) {
            const QString &id = op.features.at(j);
            const QString field = path + QStringLiteral(".features[%1]").arg(j);
            if (!ids.contains(id))
                out.push_back(makeError(field, Operations::tr("there is no feature \"%1\"").arg(id)));
            else if (!named.insert(id).second)
                out.push_back(makeError(field, Operations::tr("feature %1 is named by two operations").arg(id)));
        }
    }
    if (hasErrors(out))
        return out;
    if (operationFeatures(project, 0).isEmpty())
        out.push_back(makeError(
            QStringLiteral("further_operations"),
            Operations::tr("%1 cuts no feature: the later operations name them all").arg(operationName(project, 0))));
    for (int k = 0; k < operationCount(project); ++k)
        checkReach(project, k, out);
    return out;
}

} // namespace tolturn
