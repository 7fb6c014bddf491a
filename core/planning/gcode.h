// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/data/data_library.h"
#include "core/deviation/turning_inputs.h"
#include "core/planning/compensation.h"
#include "core/planning/post_processor.h"
#include "core/planning/toolpath.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace tolturn {

struct GCodeOptions {
    std::optional<ControlDialect> dialect; // unset: the machine's control, else Fanuc/Haas (said in the header)
    NoseHandling nose = NoseHandling::ControlCompensation;
    const CompensationPlan *compensation = nullptr; // nullptr: the target contour as it is
    int tool = 1;
    int programNumber = 1000;
    double clearance_mm = 2.0;
};

struct TurningProgram {
    QString text;
    ControlDialect dialect = ControlDialect::FanucHaas;
    QString dialectReason; // the machine's control, the caller's choice, or the default
    Toolpath path;
    SpindleLimit spindle;
    QString conditions; // the passes the program cuts, in words (for the G-code tab and the report)
};

// The program that turns a project's part on its machine: the roughing passes the project plans
// (project.passes, kind roughing) and the finishing pass, along the contour the verdicts assume
// (targetContour(): every toleranced diameter at the middle of its zone, MODEL §3), corrected
// where the compensation plan says, in the dialect of the machine's control. `inputs` are the
// project resolved against the data (nose radius, entering angle, finishing pass, spindle limit).
[[nodiscard]] TurningProgram turningProgram(const Project &project, const DataLibrary &data,
                                            const TurningInputs &inputs, const GCodeOptions &options);

// The control dialect of a machine in the data library, if it has a CNC control.
[[nodiscard]] std::optional<ControlDialect> machineDialect(const DataLibrary &data, const QString &machineId);

[[nodiscard]] QString keyword(NoseHandling nose); // "control", "tip-path"
[[nodiscard]] std::optional<NoseHandling> noseHandlingFromKeyword(const QString &text);

} // namespace tolturn
