// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/spin_box_steps.h"

#include "widgets/document/project_document.h"

#include <QDoubleSpinBox>

#include <utility>

namespace tolturn {

void connectSpinBoxSteps(QDoubleSpinBox *box, ProjectDocument &document, QObject *context, std::function<void()> apply)
{
    QObject::connect(box, &QDoubleSpinBox::valueChanged, context, [box, &document, apply = std::move(apply)] {
        const ProjectDocument::RepeatedEdits steps(document, box);
        apply();
    });
    // Return, or the focus gone elsewhere: the next steps are a step of their own.
    QObject::connect(box, &QAbstractSpinBox::editingFinished, context, [&document] { document.endRepeatedEdits(); });
}

} // namespace tolturn
