// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The process models of Čuš & Župerl's constant-roughness control (seed 004, §2.3, eq. 2–6): the
// genetic-programming fits M1–M5 of their end-milling cuts, kept as data a user can replace
// (resources/data/surface-control-models.json carries the printed coefficients, docs/adaptive.md
// says which of the paper's own numbers they reproduce).

#include "core/common/diagnostic.h"

#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// The forms the paper's models take.
//  - Polynomial: y = c0 + c1 x + c2 x² + … (eq. 2, 3, 6)
//  - Exponential: y = c0 e^(c1 x) (eq. 4)
//  - CuttingDynamics: F = c0 (1 − c1 n³ − (c2 / f) ln(c3 f)), n [1/min], f [mm/min] (eq. 5)
enum class ProcessModelForm { Polynomial, Exponential, CuttingDynamics };

struct ProcessModel {
    ProcessModelForm form = ProcessModelForm::Polynomial;
    std::vector<double> coefficients;
    QString equation; // as the source prints it

    // x: the one input (Polynomial, Exponential); for CuttingDynamics x = n [1/min], y = f [mm/min].
    [[nodiscard]] double evaluate(double x, double y = 0.0) const;
};

struct SurfaceControlModels {
    ProcessModel forceForRoughness; // M1: F [N] that gives Ra [µm]
    ProcessModel feedCommand;       // M2: f_c [mm/min] for F [N]
    ProcessModel speedCommand;      // M3: n_c [1/min] for F [N]
    ProcessModel cuttingForce;      // M4: F [N] at n [1/min], f [mm/min]
    ProcessModel roughness;         // M5 = M6: Ra [µm] at F [N]
    QString source;
};

struct SurfaceControlModelsResult {
    std::optional<SurfaceControlModels> models;
    Diagnostics diagnostics;
};

// Reads a models file (the form of resources/data/surface-control-models.json); every problem
// names its field.
[[nodiscard]] SurfaceControlModelsResult parseSurfaceControlModels(const QJsonObject &root);
[[nodiscard]] SurfaceControlModelsResult readSurfaceControlModels(const QString &path);

// The coefficients 004 prints, as shipped.
[[nodiscard]] const SurfaceControlModels &printedSurfaceControlModels();

} // namespace tolturn
