// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The operations (set-ups) of a project and the view of one of them (docs/operations.md). The
// project's own clamping, tool, boring tool and passes are its first operation, which cuts every
// turned feature no later operation names; each further operation names the features it cuts.
// The physics, the verdicts and the plan of an operation are computed on its view: a project of
// that one set-up, the part turned end for end when the operation holds its right end, the outer
// features later operations turn still at the stock, and only the tolerances of its features.

#include "core/common/diagnostic.h"
#include "core/data/data_library.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

namespace tolturn {

[[nodiscard]] int operationCount(const Project &project);
// "OP 10", "OP 20", ... unless the project names them.
[[nodiscard]] QString operationName(const Project &project, int index);
[[nodiscard]] const Clamping &operationClamping(const Project &project, int index);

// The ids of the turned features (every segment of either contour) operation `index` cuts.
[[nodiscard]] QStringList operationFeatures(const Project &project, int index);
// The operation that cuts a feature: the first later operation that names it, else the first.
[[nodiscard]] int operationOf(const Project &project, const QString &featureId);

// The part seen from the end an operation holds: z measured from that end. Holding the left end
// it is the drawing's part; holding the right end it is mirrored (z' = L - z), the segments in
// reverse order with the same ids.
[[nodiscard]] PartProfile partAsHeld(const PartProfile &part, PartEnd heldEnd);

// The project of operation `index` alone (see above); its `scope` says which it is. A project of
// one operation is returned as it is, its part turned end for end if it is held at its right end.
// Everything computed of a set-up is computed on its view.
[[nodiscard]] Project operationView(const Project &project, int index);

// Whether a project (or the view of one operation) cuts any bore.
[[nodiscard]] bool cutsBores(const Project &project);

// Which tolerances relate features cut in different operations (a datum cut in one set-up, the
// toleranced feature in another): they carry the error of clamping the part again.
[[nodiscard]] bool spansOperations(const Project &project, const Tolerance &tolerance);

// The error of clamping the part again that a tolerance spanning operations carries, as the range
// 0 … max_um: the chuck maker's concentricity error for coaxiality and radial run-out (a shift of
// the axis of e moves the surface by up to 2e in a run-out reading and a coaxiality zone is a
// diameter, so the concentricity error as the maker prints it, a run-out reading, is taken as it
// is), its axial run-out error for perpendicularity, parallelism and axial run-out. nullopt where
// the tolerance does not span operations or the data give no value.
struct ReclampingError {
    double max_um = 0.0;
    QString source;
};

[[nodiscard]] std::optional<ReclampingError> reclampingError(const Project &project, const Tolerance &tolerance,
                                                             const DataLibrary &data);

// For people: which operations a tolerance spans, the re-clamping error it adds, and the largest
// re-clamping error with which it still holds (`value_um`, `limit_um`: its predicted value and limit).
[[nodiscard]] QString reclampingText(const Project &project, const Tolerance &tolerance, const ReclampingError &error,
                                     std::optional<double> value_um, std::optional<double> limit_um);

// For a part of one set-up held in a chuck, whose jaws cover features no tool reaches there: the
// second operation proposed (docs/operations.md, "Proposing a split"): the part turned end for end,
// held on the outer cylinder at its other end (at most a third of the part), cutting the features
// the first set-up's jaws cover. nullopt, with `why` saying why, where nothing lies in the jaws or
// no outer cylinder outside them can hold the part.
struct SplitProposal {
    Operation second;
    QString reason;
};

// The length a chuck grips on a cylinder of `available_mm`, at most a third of a part of
// `partLength_mm` (a longer grip leaves too little to turn; the third is this program's rule),
// rounded down to the 0.1 mm a setter sets a jaw stop to.
[[nodiscard]] double proposedGripLength_mm(double available_mm, double partLength_mm);

[[nodiscard]] std::optional<SplitProposal> proposeSplit(const Project &project, QString *why = nullptr);

// Named findings about the operations: names, features that do not exist or are named twice, a
// feature inside the jaws of the operation that cuts it (no tool reaches it there).
[[nodiscard]] Diagnostics checkOperations(const Project &project);

} // namespace tolturn
