// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The mean forces of peripheral end milling with the linear edge-force model (Altintas,
// Manufacturing Automation, 2nd ed., Cambridge 2012, §2.4: eq. 2.52 for the forces on a tooth,
// the averages over a revolution in closed form). They stand in for the cut data Čuš & Župerl
// trained their network on ([20], not published): docs/adaptive.md §9.

namespace tolturn {

// Cutting (…c, N/mm²) and edge (…e, N/mm) coefficients in the tangential, radial and axial
// directions of the edge.
struct MillingForceCoefficients {
    double tangentialCutting_N_mm2 = 0.0;
    double radialCutting_N_mm2 = 0.0;
    double axialCutting_N_mm2 = 0.0;
    double tangentialEdge_N_mm = 0.0;
    double radialEdge_N_mm = 0.0;
    double axialEdge_N_mm = 0.0;

    friend bool operator==(const MillingForceCoefficients &, const MillingForceCoefficients &) = default;
};

struct EndMillingCut {
    int flutes = 0;
    double axialDepth_mm = 0.0;
    double feedPerTooth_mm = 0.0;
    // Immersion angles where a tooth enters and leaves the cut, measured clockwise from +y (the
    // normal to the feed), Altintas §2.4: up milling enters at 0, down milling leaves at π.
    double entryAngle_rad = 0.0;
    double exitAngle_rad = 0.0;
};

struct MillingForces {
    double x_N = 0.0; // feed direction
    double y_N = 0.0; // normal to the feed in the plane of the cut
    double z_N = 0.0; // along the tool axis
};

// The forces on one tooth at immersion angle φ (Altintas eq. 2.52–2.54): h = c sin φ, F_t =
// K_tc a h + K_te a, F_r = K_rc a h + K_re a, F_a = K_ac a h + K_ae a, in x–y–z
// F_x = −F_t cos φ − F_r sin φ, F_y = F_t sin φ − F_r cos φ, F_z = F_a; zero outside the cut.
[[nodiscard]] MillingForces toothForces(const MillingForceCoefficients &k, const EndMillingCut &cut, double phi_rad);

// The forces averaged over a revolution, (N / 2π) ∫ over [φ_st, φ_ex] of the tooth forces, in closed
// form (Altintas eq. 2.55–2.57): what a dynamometer low-passed below the tooth frequency measures.
[[nodiscard]] MillingForces meanMillingForces(const MillingForceCoefficients &k, const EndMillingCut &cut);

// Immersion of a cut of radial depth a_e on a tool of diameter D: down milling exits at π and
// enters at π − acos(1 − 2 a_e / D); up milling enters at 0.
[[nodiscard]] EndMillingCut downMilling(int flutes, double diameter_mm, double radialDepth_mm, double axialDepth_mm,
                                        double feedPerTooth_mm);

} // namespace tolturn
