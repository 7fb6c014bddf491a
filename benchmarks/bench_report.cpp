// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the PDF report (issue 6 asks for under 2 s), results recorded in docs/benchmarks.md:
// File > Export Report / `tolturn-cli report` for each bundled example, including the deviation,
// the optimisation, the 64 x 64 cutting window, the clamping ranking and the PDF writing.
// Run: QT_QPA_PLATFORM=offscreen build/<preset>/benchmarks/bench_report
#include "benchmarks/bench_timing.h"

#include "core/io/project_file.h"
#include "widgets/report/report_writer.h"

#include <QApplication>
#include <QDir>
#include <QTemporaryDir>

#include <cstdio>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const QDir examples(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples"));
    QTemporaryDir out;
    std::printf("%-36s %6s %12s\n", "example", "pages", "median [ms]");
    for (const QString &name : examples.entryList({QStringLiteral("*.tolturn")}, QDir::Files, QDir::Name)) {
        const ProjectParseResult read = readProjectFile(examples.filePath(name));
        if (!read.project) {
            std::printf("cannot read %s\n", qPrintable(name));
            return 1;
        }
        int pages = 0;
        const QString pdf = out.filePath(name + QStringLiteral(".pdf"));
        const double ms = medianMilliseconds(7, [&] {
            pages = writeReport(*read.project, {name, {}, nullptr}, pdf).pages;
        });
        std::printf("%-36s %6d %12.1f\n", qPrintable(name), pages, ms);
    }
    return 0;
}
