// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/progress.h"
#include "core/learning/machine_learning.h"
#include "core/project/project.h"

#include <QByteArray>
#include <QString>

#include <functional>
#include <memory>

namespace tolturn {

struct ReportResult {
    bool ok = false;
    QString error; // what went wrong, naming the file
    int pages = 0;
    bool cancelled = false; // stopped through `progress`; no file was written
};

// Who and what the report's title block names besides the project's own data (part name, drawing
// number, revision, material): the project file's name and the planner (from the preferences);
// and what the predictions rest on besides the physics: what was learned of the machine from its
// measured parts, when the planner uses it (docs/learning.md).
struct ReportHeader {
    QString projectName;
    QString planner;
    std::shared_ptr<const LoadedModel> learned = nullptr;
};

// Writes the PDF report of a project (File > Export Report, `tolturn-cli report`): title block,
// the part drawing, the inputs (material, machine, tool, clamping, passes), the deviation plots
// per contribution, the tolerance verdicts, the plan with the cutting window, the clamping
// ranking and the compensation, the assumptions and the sources of the model and the data, with
// page numbers. Drawing and plots are vectors. Needs a QApplication (offscreen is enough). The
// file is written atomically. `progress` is told 0…1; a stop cancels.
[[nodiscard]] ReportResult writeReport(const Project &project, const ReportHeader &header, const QString &pdfPath,
                                       const Progress &progress = {});

// The same report as PDF bytes in memory (for standard output); `pages` set, `error` empty.
struct RenderedReport {
    QByteArray pdf;
    int pages = 0;
    bool cancelled = false;
};

[[nodiscard]] RenderedReport renderReport(const Project &project, const ReportHeader &header,
                                          const Progress &progress = {});

} // namespace tolturn
