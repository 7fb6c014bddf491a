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

// What the report computes before it draws: the predictions over the machine's stiffness range
// (or with what was learned), the finishing output, the plan, the feed schedule and the milled
// features' evaluations. Made without widgets, so that File > Export Report computes it off the
// window's thread and only draws on it.
struct ReportData;

// The report's computations for `project`; `progress` is told 0…1, and nullptr is returned once it
// is stopped. Safe on any thread.
[[nodiscard]] std::shared_ptr<const ReportData> computeReport(const Project &project, const ReportHeader &header,
                                                              const Progress &progress = {});

// The PDF report of a project (File > Export Report, `tolturn-cli report`): title block, the part
// drawing, the inputs (material, machine, tool, clamping, passes), the deviation plots per
// contribution, the tolerance verdicts, the plan with the cutting window, the clamping ranking and
// the compensation, the assumptions and the sources of the model and the data, with page numbers.
// Drawing and plots are vectors. Drawn from `data` (computeReport of the same project and header)
// on the thread of the QApplication (offscreen is enough): the plots are widgets. The file is
// written atomically.
[[nodiscard]] ReportResult writeReport(const Project &project, const ReportHeader &header, const ReportData &data,
                                       const QString &pdfPath);

// computeReport, then writeReport; a stop through `progress` cancels.
[[nodiscard]] ReportResult writeReport(const Project &project, const ReportHeader &header, const QString &pdfPath,
                                       const Progress &progress = {});

// The same report as PDF bytes in memory (for standard output); `pages` set, `error` empty.
struct RenderedReport {
    QByteArray pdf;
    int pages = 0;
    bool cancelled = false;
};

[[nodiscard]] RenderedReport renderReport(const Project &project, const ReportHeader &header, const ReportData &data);
[[nodiscard]] RenderedReport renderReport(const Project &project, const ReportHeader &header,
                                          const Progress &progress = {});

} // namespace tolturn
