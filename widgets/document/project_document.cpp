// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/project_document.h"

#include "core/io/project_json.h"
#include "core/project/project_validation.h"

#include <QFileInfo>
#include <QStringList>
#include <QUndoCommand>
#include <QUndoStack>

#include <algorithm>
#include <utility>

namespace tolturn {

namespace {

Diagnostics errorsOf(const Project &project)
{
    Diagnostics errors;
    for (Diagnostic &d : validateProject(project)) {
        if (d.severity == Severity::Error)
            errors.push_back(std::move(d));
    }
    return errors;
}

} // namespace

// A change of one member of the project (the tolerances, the passes, the tool, …): its value
// before and after; the rest of the project is not kept. Edits of one member by one control, one
// after another (the clicks on a spin box's arrows, the keys typed into it), are one step in Undo,
// as KDE Step merges repeated edits of a property (CommandEditProperty::mergeWith); an edit that
// brings the member back to where the step began removes the step.
template <typename T>
class FieldCommand : public QUndoCommand {
public:
    struct Source {
        const QObject *control = nullptr; // the spin box whose steps these are; null: a step of its own
        quint64 run = 0;                  // ProjectDocument::endRepeatedEdits
    };

    FieldCommand(ProjectDocument &doc, T Project::*field, T before, T after, const QString &text, Source source)
        : QUndoCommand(text)
        , m_doc(doc)
        , m_field(field)
        , m_before(std::move(before))
        , m_after(std::move(after))
        , m_source(source)
    {
    }

    void undo() override { apply(m_before); }

    void redo() override { apply(m_after); }

    // One id for the edits made by a control; mergeWith tells the controls and members apart.
    [[nodiscard]] int id() const override { return m_source.control ? 1 : -1; }

    bool mergeWith(const QUndoCommand *other) override
    {
        const auto *next = dynamic_cast<const FieldCommand<T> *>(other);
        if (!next || next->m_source.control != m_source.control || next->m_source.run != m_source.run ||
            next->m_field != m_field || next->text() != text())
            return false;
        m_after = next->m_after;
        setObsolete(m_after == m_before);
        return true;
    }

private:
    // The document tells its views once the push or the move through the history is over
    // (ProjectDocument::emitChange), not once per command.
    void apply(const T &value)
    {
        m_doc.m_project.*m_field = value;
        m_doc.m_changePending = true;
    }

    ProjectDocument &m_doc;
    T Project::*m_field;
    T m_before;
    T m_after;
    Source m_source;
};

ProjectDocument::ProjectDocument(QObject *parent) : QObject(parent), m_undoStack(new QUndoStack(this))
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { Q_EMIT modifiedChanged(!clean); });
    // A push (merged or not), Undo, Redo and a jump through the history (QUndoStack::setIndex,
    // which undoes or redoes several commands) each end with one indexChanged: one projectChanged
    // for all the commands they applied.
    connect(m_undoStack, &QUndoStack::indexChanged, this, &ProjectDocument::emitChange);
}

void ProjectDocument::emitChange()
{
    if (std::exchange(m_changePending, false))
        Q_EMIT projectChanged();
}

ProjectDocument::~ProjectDocument() = default;

bool ProjectDocument::isModified() const
{
    return !m_undoStack->isClean();
}

QString ProjectDocument::displayName() const
{
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).fileName();
    if (!m_project.part.name.isEmpty())
        return m_project.part.name;
    return tr("Untitled");
}

void ProjectDocument::load(Project project, const QString &filePath, const Diagnostics &readProblems)
{
    m_project = std::move(project);
    const Diagnostics seenNow = errorsOf(m_project);
    m_readProblems.clear();
    for (const Diagnostic &d : readProblems) {
        if (d.severity == Severity::Error && std::find(seenNow.begin(), seenNow.end(), d) == seenNow.end())
            m_readProblems.push_back({d, projectValueAt(m_project, d.field)});
    }
    m_hasProject = true;
    const bool pathChanged = m_filePath != filePath;
    m_filePath = filePath;
    m_undoStack->clear();
    if (pathChanged)
        Q_EMIT filePathChanged(m_filePath);
    Q_EMIT modifiedChanged(false);
    Q_EMIT projectChanged();
}

void ProjectDocument::clear()
{
    m_project = Project{};
    m_readProblems.clear();
    m_hasProject = false;
    m_filePath.clear();
    m_undoStack->clear();
    Q_EMIT filePathChanged(m_filePath);
    Q_EMIT modifiedChanged(false);
    Q_EMIT projectChanged();
}

void ProjectDocument::markRecovered()
{
    m_undoStack->resetClean(); // no state of the history matches the file any more
}

void ProjectDocument::markSaved(const QString &filePath)
{
    const bool pathChanged = m_filePath != filePath;
    m_filePath = filePath;
    m_undoStack->setClean();
    if (pathChanged)
        Q_EMIT filePathChanged(m_filePath);
    if (!m_readProblems.empty()) { // the file now holds the values shown, not the unreadable ones
        m_readProblems.clear();
        Q_EMIT projectChanged();
    }
}

Diagnostics ProjectDocument::problems() const
{
    if (!m_hasProject)
        return {};
    Diagnostics all;
    for (const ReadProblem &r : m_readProblems) {
        // A value that could not be read stays a problem until the user gives the field a value.
        if (projectValueAt(m_project, r.diagnostic.field) == r.valueAsRead)
            all.push_back(r.diagnostic);
    }
    const Diagnostics now = errorsOf(m_project);
    all.insert(all.end(), now.begin(), now.end());
    return all;
}

Diagnostics ProjectDocument::check(const Project &candidate) const
{
    // Problems are matched by their text, not their field: an edit that renumbers features or
    // tolerances moves a problem the project already had to another index without adding one.
    QStringList before;
    for (const Diagnostic &d : errorsOf(m_project))
        before << d.message;
    Diagnostics added;
    for (Diagnostic &d : errorsOf(candidate)) {
        if (!before.removeOne(d.message))
            added.push_back(std::move(d));
    }
    return added;
}

Diagnostics ProjectDocument::addTolerance(const Tolerance &tolerance)
{
    Project candidate = m_project;
    candidate.tolerances.push_back(tolerance);
    Diagnostics errors = check(candidate);
    if (errors.empty())
        pushField(&Project::tolerances, candidate.tolerances, tr("Add tolerance %1").arg(tolerance.id));
    return errors;
}

Diagnostics ProjectDocument::replaceTolerance(int index, const Tolerance &tolerance)
{
    if (index < 0 || index >= static_cast<int>(m_project.tolerances.size()))
        return {makeError(QStringLiteral("tolerances"), tr("there is no tolerance %1").arg(index))};
    Project candidate = m_project;
    candidate.tolerances[static_cast<std::size_t>(index)] = tolerance;
    Diagnostics errors = check(candidate);
    if (errors.empty())
        pushField(&Project::tolerances, candidate.tolerances, tr("Edit tolerance %1").arg(tolerance.id));
    return errors;
}

Diagnostics ProjectDocument::removeTolerance(int index)
{
    if (index < 0 || index >= static_cast<int>(m_project.tolerances.size()))
        return {makeError(QStringLiteral("tolerances"), tr("there is no tolerance %1").arg(index))};
    Project candidate = m_project;
    const QString id = candidate.tolerances[static_cast<std::size_t>(index)].id;
    candidate.tolerances.erase(candidate.tolerances.begin() + index);
    // Never refused: a tolerance that is gone leaves no error behind it.
    pushField(&Project::tolerances, candidate.tolerances, tr("Remove tolerance %1").arg(id));
    return {};
}

Diagnostics ProjectDocument::setDatum(const Datum &datum)
{
    Project candidate = m_project;
    bool replaced = false;
    for (Datum &d : candidate.datums) {
        if (d.label == datum.label) {
            d.featureId = datum.featureId;
            replaced = true;
        }
    }
    if (!replaced)
        candidate.datums.push_back(datum);
    Diagnostics errors = check(candidate);
    if (errors.empty())
        pushField(&Project::datums, candidate.datums, tr("Set datum %1 on %2").arg(datum.label, datum.featureId));
    return errors;
}

template <typename T>
void ProjectDocument::pushField(T Project::*field, const T &value, const QString &description)
{
    m_undoStack->push(
        new FieldCommand<T>(*this, field, m_project.*field, value, description, {m_repeatingControl, m_editRun}));
}

template <typename T>
Diagnostics ProjectDocument::editField(T Project::*field, const T &value, const QString &description)
{
    if (m_project.*field == value)
        return {};
    Project candidate = m_project;
    candidate.*field = value;
    Diagnostics errors = check(candidate);
    if (errors.empty())
        pushField(field, value, description);
    return errors;
}

Diagnostics ProjectDocument::setPlanning(const PlanningSettings &planning)
{
    return editField(&Project::planning, planning, tr("Change planning settings"));
}

Diagnostics ProjectDocument::setPasses(const std::vector<CuttingPass> &passes, const QString &description)
{
    return editField(&Project::passes, passes, description);
}

namespace {

// An edit of a set-up the project does not have (any more): refused, named.
Diagnostic noSuchOperation(int index)
{
    return makeError(QStringLiteral("further_operations"),
                     ProjectDocument::tr("the project has no operation %1 any more").arg(index + 1));
}

} // namespace

template <typename T>
Diagnostics ProjectDocument::editOperation(int index, T Operation::*field, const T &value, const QString &description)
{
    std::vector<Operation> operations = project().furtherOperations;
    if (index < 1 || static_cast<std::size_t>(index) > operations.size())
        return {noSuchOperation(index)};
    operations[static_cast<std::size_t>(index - 1)].*field = value;
    return editField(&Project::furtherOperations, operations, description);
}

Diagnostics ProjectDocument::setOperationPasses(int index, const std::vector<CuttingPass> &passes,
                                                const QString &description)
{
    return index <= 0 ? setPasses(passes, description) : editOperation(index, &Operation::passes, passes, description);
}

Diagnostics ProjectDocument::setFurtherOperations(const std::vector<Operation> &operations)
{
    return editField(&Project::furtherOperations, operations, tr("Change operations"));
}

Diagnostics ProjectDocument::setMilledFeatures(const std::vector<MilledFeature> &features, const QString &description)
{
    return editField(&Project::milledFeatures, features, description);
}

Diagnostics ProjectDocument::setOperationTool(int index, const Tool &tool)
{
    return index <= 0 ? setTool(tool) : editOperation(index, &Operation::tool, tool, tr("Change tool"));
}

Diagnostics ProjectDocument::setOperationBoringTool(int index, const std::optional<Tool> &tool)
{
    return index <= 0 ? setBoringTool(tool)
                      : editOperation(index, &Operation::boringTool, tool, tr("Change boring bar"));
}

Diagnostics ProjectDocument::setOperationClamping(int index, const Clamping &clamping)
{
    return index <= 0 ? setClamping(clamping)
                      : editOperation(index, &Operation::clamping, clamping, tr("Change clamping"));
}

Diagnostics ProjectDocument::setMaterial(const QString &materialId)
{
    return editField(&Project::materialId, materialId, tr("Change material to %1").arg(materialId));
}

Diagnostics ProjectDocument::setMachine(const QString &machineId)
{
    return editField(&Project::machineId, machineId, tr("Change machine to %1").arg(machineId));
}

Diagnostics ProjectDocument::setTool(const Tool &tool)
{
    return editField(&Project::tool, tool, tr("Change tool"));
}

Diagnostics ProjectDocument::setBoringTool(const std::optional<Tool> &tool)
{
    return editField(&Project::boringTool, tool, tr("Change boring bar"));
}

Diagnostics ProjectDocument::setCuttingModel(const CuttingModel &model)
{
    return editField(&Project::cuttingModel, model, tr("Change force model"));
}

Diagnostics ProjectDocument::setEnvironment(const Environment &environment)
{
    return editField(&Project::environment, environment, tr("Change shop conditions"));
}

Diagnostics ProjectDocument::setClamping(const Clamping &clamping)
{
    return editField(&Project::clamping, clamping, tr("Change clamping"));
}

Diagnostics ProjectDocument::setCharacterisation(const MachineCharacterisation &characterisation)
{
    return editField(&Project::characterisation, characterisation, tr("Change machine stiffness"));
}

Diagnostics ProjectDocument::setPart(const PartProfile &part, const QString &description)
{
    return editField(&Project::part, part, description);
}

ProjectDocument::RepeatedEdits::RepeatedEdits(ProjectDocument &document, const QObject *control)
    : m_document(document)
    , m_previous(std::exchange(document.m_repeatingControl, control))
{
}

ProjectDocument::RepeatedEdits::~RepeatedEdits()
{
    m_document.m_repeatingControl = m_previous;
}

QString ProjectDocument::nextToleranceId() const
{
    for (int n = 1;; ++n) {
        QString id = QStringLiteral("T%1").arg(n);
        bool used = false;
        for (const Tolerance &t : m_project.tolerances)
            used = used || t.id == id;
        if (!used)
            return id;
    }
}

} // namespace tolturn
