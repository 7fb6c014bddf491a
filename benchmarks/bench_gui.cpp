// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the desktop program (issue 6), results recorded in docs/benchmarks.md:
//  1. an edit of a 31-segment part until every view has redrawn (drawing, deviation curves,
//     verdicts, set-up, planning settings): the document edit, the recomputation and a full
//     paint of the window;
//  2. cold start to a usable window: the program started on an example until its window is
//     shown and painted (TOLTURN_QUIT_WHEN_SHOWN makes it quit right then).
// Run: QT_QPA_PLATFORM=offscreen build/<preset>/benchmarks/bench_gui
#include "benchmarks/bench_timing.h"

#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "core/part/profile_editing.h"
#include "widgets/document/project_document.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QStandardPaths>

#include <cstdio>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

namespace {

// A shaft of 14 steps down from Ø80: 15 cylinders and 16 faces, 31 segments, with an h7
// diameter tolerance on every cylinder.
Project thirtySegmentShaft(Project project)
{
    PartProfile &p = project.part;
    p.outer.segments.clear();
    double r = 40.0;
    double z = 0.0;
    int id = 1;
    const auto add = [&](SegmentKind kind, ProfilePoint from, ProfilePoint to) {
        Segment s;
        s.id = QStringLiteral("O%1").arg(id++);
        s.kind = kind;
        s.from = from;
        s.to = to;
        p.outer.segments.push_back(s);
    };
    add(SegmentKind::Face, {0.0, 0.0}, {0.0, r});
    project.tolerances.clear();
    project.datums.clear();
    for (int step = 0; step < 15; ++step) {
        add(SegmentKind::Cylinder, {z, r}, {z + 20.0, r});
        Tolerance t;
        t.id = QStringLiteral("T%1").arg(step + 1);
        t.type = ToleranceType::Diameter;
        t.featureId = p.outer.segments.back().id;
        t.iso286Class = QStringLiteral("h7");
        project.tolerances.push_back(t);
        z += 20.0;
        const double next = step < 14 ? r - 2.0 : 0.0;
        add(SegmentKind::Face, {z, r}, {z, next});
        r = next;
    }
    p.stockDiameter_mm = 85.0;
    project.clamping.clampedLength_mm = 20.0;
    return project;
}

double editAndRedraw(MainWindow &window)
{
    ProjectDocument &doc = *window.document();
    bool wider = false;
    return medianMilliseconds(21, [&] {
        wider = !wider;
        // The Ø72 cylinder O6 (z 40 … 60) one millimetre larger or back.
        const ProfileEdit edit = moveVertex(doc.project().part, ContourSide::Outer, 5, {40.0, wider ? 36.5 : 36.0});
        (void)doc.setPart(std::get<PartProfile>(edit), QStringLiteral("bench"));
        QCoreApplication::processEvents();
        (void)window.grab(); // paint every view
    });
}

double coldStart(const QString &program, const QString &project)
{
    return medianMilliseconds(7, [&] {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("TOLTURN_QUIT_WHEN_SHOWN"), QStringLiteral("1"));
        p.setProcessEnvironment(env);
        p.start(program, {project});
        p.waitForFinished(30000);
    });
}

} // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    const QString example = QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn");
    MainWindow window;
    window.resize(1600, 950);
    window.show();
    if (!window.fileController()->openFile(example))
        return 1;
    window.document()->load(thirtySegmentShaft(window.document()->project()), QString());
    std::printf("part: %zu segments, %zu tolerances\n", window.document()->project().part.outer.segments.size(),
                window.document()->project().tolerances.size());
    std::printf("edit of the 31-segment part until every view is redrawn: median %.1f ms\n", editAndRedraw(window));
    std::printf("cold start to a shown window (%s): median %.0f ms\n", "tolturn stepped-shaft-chuck.tolturn",
                coldStart(QStringLiteral(TOLTURN_GUI_PATH), example));
    return 0;
}
