// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/project_document.h"

#include "core/project/project_validation.h"

#include <QFileInfo>
#include <QUndoCommand>
#include <QUndoStack>

#include <utility>

namespace tolturn {

// One change of the tolerance list: the list before and after (tolerances are a handful of small
// records; the rest of the project is not kept).
class ToleranceListCommand : public QUndoCommand {
public:
    ToleranceListCommand(ProjectDocument &doc, std::vector<Tolerance> before, std::vector<Tolerance> after,
                         const QString &text)
        : QUndoCommand(text)
        , m_doc(doc)
        , m_before(std::move(before))
        , m_after(std::move(after))
    {
    }

    void undo() override { m_doc.setTolerances(m_before); }

    void redo() override { m_doc.setTolerances(m_after); }

private:
    ProjectDocument &m_doc;
    std::vector<Tolerance> m_before;
    std::vector<Tolerance> m_after;
};

class DatumListCommand : public QUndoCommand {
public:
    DatumListCommand(ProjectDocument &doc, std::vector<Datum> before, std::vector<Datum> after, const QString &text)
        : QUndoCommand(text)
        , m_doc(doc)
        , m_before(std::move(before))
        , m_after(std::move(after))
    {
    }

    void undo() override { m_doc.setDatums(m_before); }

    void redo() override { m_doc.setDatums(m_after); }

private:
    ProjectDocument &m_doc;
    std::vector<Datum> m_before;
    std::vector<Datum> m_after;
};

// A change of one member of the project (the planning settings, the passes): before and after.
template <typename T>
class FieldCommand : public QUndoCommand {
public:
    FieldCommand(ProjectDocument &doc, T Project::*field, T before, T after, const QString &text)
        : QUndoCommand(text)
        , m_doc(doc)
        , m_field(field)
        , m_before(std::move(before))
        , m_after(std::move(after))
    {
    }

    void undo() override { apply(m_before); }

    void redo() override { apply(m_after); }

private:
    void apply(const T &value)
    {
        m_doc.m_project.*m_field = value;
        Q_EMIT m_doc.projectChanged();
    }

    ProjectDocument &m_doc;
    T Project::*m_field;
    T m_before;
    T m_after;
};

ProjectDocument::ProjectDocument(QObject *parent) : QObject(parent), m_undoStack(new QUndoStack(this))
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { Q_EMIT modifiedChanged(!clean); });
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

void ProjectDocument::load(Project project, const QString &filePath)
{
    m_project = std::move(project);
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
}

Diagnostics ProjectDocument::check(const Project &candidate) const
{
    Diagnostics errors;
    for (const Diagnostic &d : validateProject(candidate)) {
        if (d.severity == Severity::Error)
            errors.push_back(d);
    }
    return errors;
}

Diagnostics ProjectDocument::addTolerance(const Tolerance &tolerance)
{
    Project candidate = m_project;
    candidate.tolerances.push_back(tolerance);
    Diagnostics errors = check(candidate);
    if (errors.empty())
        m_undoStack->push(new ToleranceListCommand(*this, m_project.tolerances, candidate.tolerances,
                                                   tr("Add tolerance %1").arg(tolerance.id)));
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
        m_undoStack->push(new ToleranceListCommand(*this, m_project.tolerances, candidate.tolerances,
                                                   tr("Edit tolerance %1").arg(tolerance.id)));
    return errors;
}

Diagnostics ProjectDocument::removeTolerance(int index)
{
    if (index < 0 || index >= static_cast<int>(m_project.tolerances.size()))
        return {makeError(QStringLiteral("tolerances"), tr("there is no tolerance %1").arg(index))};
    Project candidate = m_project;
    const QString id = candidate.tolerances[static_cast<std::size_t>(index)].id;
    candidate.tolerances.erase(candidate.tolerances.begin() + index);
    m_undoStack->push(
        new ToleranceListCommand(*this, m_project.tolerances, candidate.tolerances, tr("Remove tolerance %1").arg(id)));
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
        m_undoStack->push(new DatumListCommand(*this, m_project.datums, candidate.datums,
                                               tr("Set datum %1 on %2").arg(datum.label, datum.featureId)));
    return errors;
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
        m_undoStack->push(new FieldCommand<T>(*this, field, m_project.*field, value, description));
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

void ProjectDocument::setTolerances(std::vector<Tolerance> tolerances)
{
    m_project.tolerances = std::move(tolerances);
    Q_EMIT projectChanged();
}

void ProjectDocument::setDatums(std::vector<Datum> datums)
{
    m_project.datums = std::move(datums);
    Q_EMIT projectChanged();
}

} // namespace tolturn
