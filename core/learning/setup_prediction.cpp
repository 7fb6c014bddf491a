// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/setup_prediction.h"

#include "core/learning/measured_residuals.h"
#include "core/planning/finished_extent.h"
#include "core/project/keywords.h"

#include <QCoreApplication>

#include <utility>

namespace tolturn {

namespace {

struct SetupPredictionText {
    Q_DECLARE_TR_FUNCTIONS(SetupPrediction)
};

} // namespace

SetupPrediction predictSetup(const Project &project, const DataLibrary &data, const LoadedModel *learned)
{
    SetupPrediction p;
    // A model of another physics is not added to this one; the banner says why.
    const QString mismatch = learned ? learnedPhysicsMismatch(project, *learned) : QString();
    if (!mismatch.isEmpty())
        learned = nullptr;
    if (learned) {
        // One prediction, physics + learned, for the verdicts; the curves keep the physics'
        // contributions and add the learned total.
        p.range = evaluateWithLearned(project, data, *learned, &p.deviation);
        p.learned = LearnedCurves{learnedAtStations(project, p.deviation, learned->model), learned->uncertainty_mm(),
                                  learned->provenance()};
        p.assumption = learnedAssumptionText(*learned);
        // Where the plan lies outside what the model was learned at: withLearnedResidual said it.
        for (const Diagnostic &d : p.range.compliant.diagnostics)
            if (d.field == QLatin1String("learned")) // without its full stop, which the report adds
                p.assumption += QStringLiteral(". ") + d.message.chopped(d.message.endsWith(QLatin1Char('.')) ? 1 : 0);
    } else {
        p.range = evaluateOverStiffnessRange(project, data);
        p.deviation = p.range.compliant;
        p.stiffEnd = p.range.stiff;
        p.assumption = machineAssumptionText(p.range, data);
    }
    if (!mismatch.isEmpty())
        p.assumption = SetupPredictionText::tr("%1. Without it: %2").arg(mismatch, p.assumption);
    addReclampingNotes(project, p.range, data);
    addWhatTheProgramLeaves(project, p.range);
    if (project.scope) // one set-up of several: which, and which end of the drawing it holds
        p.assumption.prepend(SetupPredictionText::tr("%1 (set-up %2 of %3, the %4 end held): ")
                                 .arg(project.scope->name)
                                 .arg(project.scope->index + 1)
                                 .arg(project.scope->count)
                                 .arg(displayName(project.clamping.heldEnd)));
    return p;
}

} // namespace tolturn
