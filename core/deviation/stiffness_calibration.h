// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"
#include "core/data/data_library.h"
#include "core/project/project.h"

#include <optional>
#include <vector>

namespace tolturn {

// One measured point of a stiff test bar turned in the chuck (Valiño et al. 2008 §III): the
// deviation of the machined radius at z (from the part's left end) in µm, positive where material
// was left (a diameter too large); optionally the tangential deviation, where it was measured.
struct TestBarPoint {
    double z_mm = 0.0;
    double radial_um = 0.0;
    std::optional<double> tangential_um;
};

struct TestBarReadResult {
    std::optional<std::vector<TestBarPoint>> points;
    Diagnostics diagnostics;
};

// CSV with the header z_mm,radial_um[,tangential_um] (any order, comma or semicolon, '#'
// comments).
[[nodiscard]] TestBarReadResult readTestBarMeasurements(const QString &path);
[[nodiscard]] TestBarReadResult parseTestBarMeasurements(const QString &text, const QString &fileName);

// The spindle–chuck part of the measured deviation fitted by P(x) = a x² + b x + c, x the distance
// from the chuck face (Valiño §III), and the springs that polynomial gives (docs/model.md §2).
struct SpringFit {
    SpindleSprings springs;
    double a_per_mm = 0.0; // [mm/mm²]
    double b = 0.0;        // [mm/mm]
    double c_mm = 0.0;
    double rmsResidual_um = 0.0;
    int points = 0;
};

struct StiffnessCalibration {
    std::optional<SpringFit> radial;
    std::optional<SpringFit> tangential; // only when the tangential deviation was measured
    int tangentialPositions = 0;         // positions z with a tangential deviation measured
    double pivotDistance_mm = 0.0;
    CuttingForces forces;
    double diameter_mm = 0.0;
    // Share of the bar's own bending and the toolpost in the measured radial deviation at the
    // measured point farthest from the chuck (the model's prediction, subtracted before the fit).
    double barShareAtEnd = 0.0;
    Diagnostics diagnostics;
};

// Fits the spindle–chuck springs k1, k2, k3 to the measured deviation of a test bar (Valiño et al.
// 2008 §III). `testBar` is the project of the bar as it was cut: held in the chuck only, its
// part, tool, material and pass. The deviation the model predicts for the bar itself and the
// toolpost (with a rigid chuck) is subtracted from the measurement first, so the bar need not be
// infinitely stiff; what remains is fitted by P(x), and with the feed-force moment M = -F_a D/2
//   a = F s,  b = 2 F Lc/k2 + M s,  c = F/k1 + (F Lc² + M Lc)/k2,  s = 1/k2 + 1/k3
// is solved for the springs (tangentially with F_t and M = 0). `load` replaces the forces of the
// project's force model (measured forces are better). Every spring must come out positive: a
// negative one is an error that names it and its value. With any error neither fit is returned.
[[nodiscard]] StiffnessCalibration calibrateSpindleChuck(const Project &testBar, const DataLibrary &data,
                                                         const std::vector<TestBarPoint> &points,
                                                         double pivotDistance_mm,
                                                         const std::optional<CuttingForces> &load = std::nullopt);

// Why the tangential springs of `characterisation` do not survive `cal`: they were fitted for
// another Lc and `cal` fits none (the springs depend on Lc). Empty when they survive or there are none.
[[nodiscard]] QString staleTangentialSprings(const MachineCharacterisation &characterisation,
                                             const StiffnessCalibration &cal);

// `characterisation` with the fitted springs and their Lc in place (tangential only where they
// were fitted, stale ones removed, everything else kept) and `source` as where the numbers come from.
[[nodiscard]] MachineCharacterisation withFittedSprings(MachineCharacterisation characterisation,
                                                        const StiffnessCalibration &cal, const QString &source);

} // namespace tolturn
