// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/common/progress.h"
#include "core/part/profile.h"
#include "core/project/milled_feature.h"

#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace tolturn {

// Cones no longer than this along their slant, between two other segments, become chamfers
// (docs/step-import.md): the usual edge breaks of drawings (0.2 to 3 mm x 45°).
inline constexpr double kDefaultChamferMaxLength_mm = 3.0;

struct CadImportOptions {
    int solidIndex = -1;   // which body (index into CadImportResult::solids); -1: the largest
    int axisIndex = -1;    // which axis (index into CadImportResult::axes); -1: most revolved area
    bool flip = false;     // turn the part end for end: z = 0 at the other end
    double zOffset_mm = 0; // added to every z after placing z = 0 at the left end
    double chamferMaxLength_mm = kDefaultChamferMaxLength_mm;
    Progress progress; // the import's progress, 0 … 1; a stop cancels it
};

// A body of the file the caller may choose with CadImportOptions::solidIndex.
struct CadSolidInfo {
    double volume_mm3 = 0.0;
    int faceCount = 0;
};

// A candidate rotation axis: the common axis of revolved faces of the chosen body.
struct CadAxisInfo {
    double origin_mm[3] = {0.0, 0.0, 0.0};
    double direction[3] = {0.0, 0.0, 1.0};
    double revolvedArea_mm2 = 0.0; // area of the faces revolved about this axis
    int faceCount = 0;
};

struct CadImportResult {
    // Absent when the file cannot be read or holds no turned section, and on cancel. Present
    // otherwise, with validateProfile's findings among the diagnostics.
    std::optional<PartProfile> profile;
    Diagnostics diagnostics; // warnings (left-out features, profile findings) and errors
    // The flats and keyways among the faces left out, with their place on the part only (ids "M1",
    // "M2", … in z order; docs/step-import.md, "Milled features"). Empty without a profile.
    std::vector<MilledFeature> milledFeatures;
    std::vector<CadSolidInfo> solids;
    std::vector<CadAxisInfo> axes; // of the chosen solid, most revolved area first
    int chosenSolid = -1;
    int chosenAxis = -1;
    bool cancelled = false;
};

enum class CadFormat { Step, Iges };

// A STEP or IGES file read and transferred to shapes once (EXAMPLES.md item 3, after Mayo's
// readFile/transfer): its bodies, from which extractProfile builds a profile as often as the
// planner picks another body, axis or end. Reading is the slow part; an extraction traces one body.
// A copy shares the shapes.
class CadModel {
public:
    struct Bodies; // OpenCascade's shapes (step_import.cpp)

    CadModel(QString path, CadFormat format, std::shared_ptr<const Bodies> bodies, std::vector<CadSolidInfo> solids);

    [[nodiscard]] const QString &path() const { return m_path; }

    [[nodiscard]] CadFormat format() const { return m_format; }

    // The bodies, in the file's order (CadImportOptions::solidIndex counts in it).
    [[nodiscard]] const std::vector<CadSolidInfo> &solids() const { return m_solids; }

    [[nodiscard]] const Bodies &bodies() const { return *m_bodies; }

private:
    QString m_path;
    CadFormat m_format;
    std::shared_ptr<const Bodies> m_bodies;
    std::vector<CadSolidInfo> m_solids;
};

struct CadReadResult {
    std::optional<CadModel> model; // absent after an error and on cancel
    Diagnostics diagnostics;       // errors naming the file
    bool cancelled = false;
};

// Reads a STEP (.step, .stp) or IGES (.iges, .igs) file and transfers it to shapes in millimetres.
// `progress` is told 0 … 1; a stop cancels. Never throws. Safe on any thread (OpenCascade is
// locked while it works).
[[nodiscard]] CadReadResult readCadFile(const QString &path, const Progress &progress = {});

// The half-section of the body, about the axis, with the end that `options` choose, as a TolTurn
// profile, with the milled features and the notes of what was left out; `options.progress` is told
// 0 … 1 of this extraction. The result's `solids` are the model's.
[[nodiscard]] CadImportResult extractProfile(const CadModel &model, const CadImportOptions &options);

// Reads a STEP or IGES file and returns the half-section of the chosen body as a TolTurn profile:
// readCadFile, then extractProfile (the progress 80 % reading, 20 % extracting). Never throws:
// every failure is an error diagnostic naming the file.
[[nodiscard]] CadImportResult importCadFile(const QString &path, const CadImportOptions &options = {});

} // namespace tolturn
