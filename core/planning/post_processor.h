// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Programs for a lathe control from a tool path (ISO 6983-1 word address format), one dialect per
// family of controls:
//  - Fanuc/Haas (lathe G-code system A, as on Haas lathes): G50 S spindle limit, G96 constant
//    surface speed, G99 feed per revolution, G41/G42 nose radius compensation with the tip
//    direction in the geometry offset, G02/G03 with R.
//  - Siemens Sinumerik (840D/828D ISO-free dialect): LIMS= spindle limit, G96 S, G95 feed per
//    revolution, DIAMON diameter programming, G41/G42, G2/G3 with CR=, ';' comments.
//  - LinuxCNC (rs274ngc, lathe mode): G96 D (maximum spindle speed) S, G95, G7 diameter mode,
//    G41/G42 with the tool table's diameter D and orientation Q, G2/G3 with R.
// The meanings of these words are those of the makers' programming manuals (Haas lathe operator's
// manual, G-code chapter; Siemens SINUMERIK Programming Manual Fundamentals, "Spindle speed
// limitation LIMS", "Constant cutting rate G96", "Feedrate G95"; LinuxCNC G-code reference, G96/G97,
// G7, G41/G42 lathe tool orientation). The LinuxCNC output is read back by LinuxCNC's own
// interpreter in the tests.

#include "core/planning/toolpath.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace tolturn {

enum class ControlDialect { FanucHaas, Sinumerik, LinuxCnc };

[[nodiscard]] QString keyword(ControlDialect dialect); // "fanuc", "sinumerik", "linuxcnc"
[[nodiscard]] std::optional<ControlDialect> controlDialectFromKeyword(const QString &text);
[[nodiscard]] QString displayName(ControlDialect dialect);

// The spindle speed the program clamps G96 at: the highest speed any pass needs on a diameter it
// turns (a face run to the axis does not count; G96 is clamped there), no more than the machine's
// limit where one is known.
struct SpindleLimit {
    double speed_rpm = 0.0;
    QString reason; // how it was formed, for the program header and people
};

// The diameter on which a pass needs its highest spindle speed under G96: the smallest it turns,
// or for a pass that only faces, the largest it faces (the spindle holds that speed inwards).
// 0 when the pass cuts nothing.
[[nodiscard]] double speedLimitingDiameter_mm(const PassPath &pass);

// The spindle limit a program sets (G50, LIMS): the highest speed any of its passes needs under
// G96 on its speed-limiting diameter, rounded up to 1 rpm, or the machine's limit if lower.
[[nodiscard]] SpindleLimit spindleLimit(const std::vector<const Toolpath *> &paths,
                                        std::optional<double> machineLimit_rpm);

struct PostOptions {
    ControlDialect dialect = ControlDialect::FanucHaas;
    int programNumber = 1000;
    int tool = 1;
    int boringTool = 2;     // the boring bar's tool number, when there is a boring path
    QString boringToolLine; // the comment that names the boring bar before its tool call
    // Where the turret goes before the boring bar is indexed (z from the left end, r): above the
    // turning path's safe diameter and the bar's overhang plus the clearance off the end face, so
    // that neither tool sweeps the part as the turret turns.
    ProfilePoint toolChangeAt;
    SpindleLimit spindle;
    QStringList header; // lines for the comment block at the top (part, material, tool, compensation, conditions)
};

// The program: the turning path with the tool `tool`, then the boring path, if any, with the tool
// `boringTool` (its own nose handling, G41).
[[nodiscard]] QString postProcess(const Toolpath &path, const Toolpath *boring, double partLength_mm,
                                  const PostOptions &options);

// The program number as the program's O-word states it: "O01000" (five digits, as Haas numbers
// its programs, O00000 to O99999).
[[nodiscard]] QString programNumberWord(int programNumber);

} // namespace tolturn
