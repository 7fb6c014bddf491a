// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/fe/solid_check_dialog.h"

#include "core/data/data_library.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/common/worker_threads.h"
#include "widgets/fe/solid_check_view.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

namespace tolturn {

// What the worker and the dialog share: the worker writes its progress, the dialog polls it and
// asks it to stop. Owned by both, so that neither outlives the other's pointer.
struct SolidCheckRunState {
    std::atomic<bool> stop{false};
    std::atomic<int> percent{0};
    std::mutex mutex;
    QString stage; // guarded by `mutex`
};

namespace {

// Below this a mesh of a whole part has millions of elements: hours of gmsh and CalculiX and more
// memory than a workstation has.
constexpr double kFinestMesh_mm = 0.5;
constexpr int kMostStations = 50;

} // namespace

SolidCheckDialog::SolidCheckDialog(const Project &project, int operation, QWidget *parent)
    : QDialog(parent)
    , m_project(project)
    , m_operation(new QComboBox(this))
    , m_stations(new QSpinBox(this))
    , m_meshSize(new LengthSpinBox(std::max(100.0, project.part.length_mm()),
                                   tr("The largest edge of the tetrahedra gmsh meshes the part with: smaller is more "
                                      "exact and slower"),
                                   this))
    , m_meshHint(new QLabel(this))
    , m_run(new QPushButton(tr("Run"), this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
    , m_progress(new QProgressBar(this))
    , m_message(new QLabel(this))
    , m_view(new SolidCheckView(this))
{
    setObjectName(QStringLiteral("solidCheckDialog"));
    setWindowTitle(tr("Check with Solid FE"));
    setSizeGripEnabled(true);
    const int count = operationCount(m_project);
    for (int k = 0; k < count; ++k)
        m_operation->addItem(tr("%1: %2, %3 end held")
                                 .arg(operationName(m_project, k), displayName(operationClamping(m_project, k).method),
                                      displayName(operationClamping(m_project, k).heldEnd)));
    m_operation->setCurrentIndex(std::clamp(operation, 0, count - 1));
    buildLayout();
    connect(m_operation, &QComboBox::currentIndexChanged, this, &SolidCheckDialog::operationChosen);
    connect(m_run, &QPushButton::clicked, this, &SolidCheckDialog::run);
    connect(m_cancel, &QPushButton::clicked, this, &SolidCheckDialog::cancel);
    connect(&m_watcher, &QFutureWatcher<SolidCheckResult>::finished, this, &SolidCheckDialog::runFinished);
    connect(&m_poll, &QTimer::timeout, this, &SolidCheckDialog::showProgress);
    m_poll.setInterval(100);
    operationChosen();
    setRunning(false);
    resize(1040, 650); // the eight columns of the table without scrolling, on a 1366 x 768 screen
}

SolidCheckDialog::~SolidCheckDialog()
{
    waitForRun();
}

void SolidCheckDialog::buildLayout()
{
    m_message->setObjectName(QStringLiteral("solidCheckMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->setText(tr("The part of the set-up is meshed in quadratic tetrahedra with gmsh, held as its clamping "
                          "holds it, loaded by the cutting force at each station and solved with CalculiX; its "
                          "deflection is compared with the beam's. A coarse mesh takes seconds, a fine one minutes. "
                          "The project is not changed."));
    m_progress->setRange(0, 100);
    m_progress->setValue(0);
    m_progress->setTextVisible(true);
    m_progress->setFormat(QStringLiteral("%p%"));
    auto *runRow = new QHBoxLayout;
    runRow->addWidget(m_run);
    runRow->addWidget(m_cancel);
    runRow->addWidget(m_progress, 1);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &SolidCheckDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(buildControls());
    layout->addLayout(runRow);
    layout->addWidget(m_message);
    layout->addWidget(m_view, 1);
    layout->addWidget(buttons);
}

QWidget *SolidCheckDialog::buildControls()
{
    m_operation->setObjectName(QStringLiteral("solidCheckOperation"));
    m_operation->setToolTip(tr("The set-up checked: its part as held and its finishing pass's force"));
    m_stations->setObjectName(QStringLiteral("solidCheckStations"));
    m_stations->setRange(1, kMostStations);
    m_stations->setValue(SolidCheckOptions{}.stations);
    m_stations->setToolTip(tr("Tool positions, evenly along the supported length: one load case of CalculiX each"));
    m_meshSize->setObjectName(QStringLiteral("solidCheckMeshSize"));
    m_meshHint->setObjectName(QStringLiteral("solidCheckMeshHint"));
    m_meshHint->setStyleSheet(QStringLiteral("color: #555;"));
    m_run->setObjectName(QStringLiteral("solidCheckRun"));
    m_run->setDefault(true);
    m_cancel->setObjectName(QStringLiteral("solidCheckCancel"));
    auto *mesh = new QHBoxLayout;
    mesh->addWidget(m_meshSize);
    mesh->addWidget(m_meshHint, 1);
    auto *controls = new QWidget(this);
    auto *form = new QFormLayout(controls);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    form->addRow(tr("Operation:"), m_operation);
    form->addRow(tr("Stations:"), m_stations);
    form->addRow(tr("Mesh size:"), mesh);
    form->setRowVisible(m_operation, m_operation->count() > 1);
    return controls;
}

double SolidCheckDialog::defaultMeshSize_mm() const
{
    return defaultMeshSize(operationView(m_project, std::max(m_operation->currentIndex(), 0)).part);
}

// Another set-up: its part as held may have other diameters, so the default size is its own.
void SolidCheckDialog::operationChosen()
{
    const double size = defaultMeshSize_mm();
    const DisplayUnits units = DisplaySettings::instance().units();
    m_meshSize->setMillimetres(size);
    m_meshHint->setText(tr("default %1 %2: a fifth of the smallest outer diameter between the supports")
                            .arg(units.lengthText(size), units.lengthSymbol()));
}

QString SolidCheckDialog::messageText() const
{
    return m_message->text();
}

QString SolidCheckDialog::progressText() const
{
    return m_progress->text();
}

bool SolidCheckDialog::isRunning() const
{
    return m_state != nullptr;
}

void SolidCheckDialog::setRunning(bool running)
{
    m_run->setEnabled(!running);
    m_cancel->setEnabled(running);
    m_operation->setEnabled(!running);
    m_stations->setEnabled(!running);
    m_meshSize->setEnabled(!running);
}

void SolidCheckDialog::run()
{
    if (isRunning())
        return;
    SolidCheckOptions options;
    options.stations = m_stations->value();
    options.meshSize_mm = m_meshSize->millimetres();
    options.operation = m_operation->currentIndex();
    if (*options.meshSize_mm < kFinestMesh_mm) {
        const DisplayUnits units = DisplaySettings::instance().units();
        m_message->setStyleSheet(QStringLiteral("color: #a00;"));
        m_message->setText(tr("Choose a mesh size of at least %1 %2: a finer mesh of a whole part takes gmsh and "
                              "CalculiX hours and more memory than the computer has.")
                               .arg(units.lengthText(kFinestMesh_mm), units.lengthSymbol()));
        return;
    }
    m_state = std::make_shared<SolidCheckRunState>();
    const std::shared_ptr<SolidCheckRunState> state = m_state;
    const SolidCheckProgress progress = [state](int percent, const QString &stage) {
        state->percent.store(percent);
        {
            const std::lock_guard lock(state->mutex);
            state->stage = stage;
        }
        return !state->stop.load();
    };
    m_runOperation = options.operation;
    m_view->clear();
    m_message->setStyleSheet(QString());
    m_message->setText(tr("Checking…"));
    m_progress->setValue(0);
    m_progress->setFormat(QStringLiteral("%p%"));
    setRunning(true);
    m_poll.start();
    m_watcher.setFuture(QtConcurrent::run(workerThreads(), [project = m_project, options, progress] {
        return checkWithSolidFe(project, DataLibrary::builtIn(), options, progress);
    }));
}

void SolidCheckDialog::cancel()
{
    if (m_state) {
        m_state->stop.store(true);
        m_message->setText(tr("Cancelling…"));
    }
}

void SolidCheckDialog::showProgress()
{
    if (!m_state)
        return;
    QString stage;
    {
        const std::lock_guard lock(m_state->mutex);
        stage = m_state->stage;
    }
    m_progress->setValue(std::clamp(m_state->percent.load(), 0, 100));
    m_progress->setFormat(stage.isEmpty() ? QStringLiteral("%p%") : stage + QStringLiteral(" — %p%"));
}

void SolidCheckDialog::runFinished()
{
    m_poll.stop();
    m_state.reset();
    setRunning(false);
    const SolidCheckResult result = m_watcher.result();
    if (!result.ok()) {
        showFailure(result);
        Q_EMIT checkFinished();
        return;
    }
    m_progress->setValue(100);
    m_progress->setFormat(tr("done — %p%"));
    m_message->setStyleSheet(QString());
    m_message->setText(tr("Checked in %1 s. The beam's radial deflection differs from the solid's by at most %2 % of "
                          "the largest deflection.")
                           .arg(QString::number(result.meshSeconds + result.solveSeconds + result.beamSeconds, 'f', 1),
                                QString::number(result.largestRadialDifference_pct(), 'f', 1)));
    m_view->showResult(result, m_project.part.length_mm(),
                       displayName(operationClamping(m_project, m_runOperation).method));
    Q_EMIT checkFinished();
}

void SolidCheckDialog::showFailure(const SolidCheckResult &result)
{
    QStringList lines;
    switch (result.failure) {
    case SolidCheckFailure::Project:
        lines << tr("The project cannot be checked:");
        break;
    case SolidCheckFailure::MissingEngine:
        lines << tr("The check needs gmsh and CalculiX, and one of them is missing:");
        break;
    case SolidCheckFailure::Mesh:
        lines << tr("Meshing the part failed:");
        break;
    case SolidCheckFailure::Solver:
        lines << tr("Solving failed:");
        break;
    case SolidCheckFailure::Cancelled:
        lines << tr("The check was cancelled; the project is unchanged.");
        break;
    case SolidCheckFailure::None:
        break;
    }
    const bool cancelled = result.failure == SolidCheckFailure::Cancelled;
    for (const Diagnostic &d : result.diagnostics)
        if (!cancelled) // the cancellation's own diagnostic says what the line above says
            lines << (result.failure == SolidCheckFailure::Project ? d.toString() : d.message);
    m_progress->setValue(0);
    m_progress->setFormat(cancelled ? tr("cancelled") : tr("failed"));
    m_message->setStyleSheet(cancelled ? QString() : QStringLiteral("color: #a00;"));
    m_message->setText(lines.join(QLatin1Char('\n')));
    m_view->clear();
}

void SolidCheckDialog::waitForRun()
{
    if (m_state)
        m_state->stop.store(true);
    m_watcher.waitForFinished();
}

void SolidCheckDialog::reject()
{
    waitForRun();
    QDialog::reject();
}

} // namespace tolturn
