// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/common/project_fields.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QScrollArea>
#include <QStackedWidget>
#include <QStringList>
#include <QTabWidget>
#include <QVariant>
#include <QWidget>

namespace tolturn {

namespace {

constexpr char kFieldProperty[] = "projectField";
constexpr char kBaseTipProperty[] = "projectFieldBaseTip";

// Only single-value editors are coloured; a composite one (a group of boxes) keeps its look.
bool isValueEditor(const QWidget &w)
{
    return qobject_cast<const QAbstractSpinBox *>(&w) || qobject_cast<const QLineEdit *>(&w) ||
           qobject_cast<const QComboBox *>(&w);
}

// Makes `w` visible within its ancestors: the page of a tab or stack, the area of a scroll.
void revealInAncestors(QWidget &w)
{
    QWidget *child = &w;
    for (QWidget *p = w.parentWidget(); p; child = p, p = p->parentWidget()) {
        if (auto *stack = qobject_cast<QStackedWidget *>(p)) {
            stack->setCurrentWidget(child);
            if (auto *tabs = qobject_cast<QTabWidget *>(stack->parentWidget()))
                tabs->setCurrentWidget(child);
        } else if (auto *dock = qobject_cast<QDockWidget *>(p)) {
            dock->show();
            dock->raise();
        }
    }
    for (QWidget *p = w.parentWidget(); p; p = p->parentWidget()) {
        if (auto *scroll = qobject_cast<QScrollArea *>(p); scroll && scroll->widget())
            scroll->ensureWidgetVisible(&w);
    }
}

} // namespace

void setProjectField(QWidget &editor, const QString &field)
{
    editor.setProperty(kFieldProperty, field);
}

QString projectField(const QWidget &editor)
{
    return editor.property(kFieldProperty).toString();
}

bool fieldCovers(const QString &editorField, const QString &field)
{
    if (editorField.isEmpty() || !field.startsWith(editorField))
        return false;
    if (field.size() == editorField.size())
        return true;
    const QChar next = field.at(editorField.size());
    return next == QLatin1Char('.') || next == QLatin1Char('[');
}

void markFindings(QWidget &root, const Diagnostics &findings)
{
    for (QWidget *w : root.findChildren<QWidget *>()) {
        const QString field = projectField(*w);
        if (field.isEmpty() || !isValueEditor(*w))
            continue;
        if (!w->property(kBaseTipProperty).isValid())
            w->setProperty(kBaseTipProperty, w->toolTip());
        QStringList messages;
        bool error = false;
        for (const Diagnostic &d : findings) {
            if (d.field == field) {
                messages << d.message;
                error = error || d.severity == Severity::Error;
            }
        }
        // Red for what stops the computation, amber for what is only outside a published range.
        w->setStyleSheet(messages.isEmpty() ? QString()
                         : error            ? QStringLiteral("background: #fcbba1;")
                                            : QStringLiteral("background: #ffe8a3;"));
        const QString base = w->property(kBaseTipProperty).toString();
        w->setToolTip(messages.isEmpty() ? base
                                         : base + (base.isEmpty() ? QString() : QStringLiteral("\n\n")) +
                                               messages.join(QLatin1Char('\n')));
    }
}

QWidget *editorForField(QWidget &root, const QString &field)
{
    QWidget *best = nullptr;
    qsizetype bestLength = -1;
    for (QWidget *w : root.findChildren<QWidget *>()) {
        const QString editorField = projectField(*w);
        if (fieldCovers(editorField, field) && editorField.size() > bestLength) {
            best = w;
            bestLength = editorField.size();
        }
    }
    return best;
}

void focusEditor(QWidget &editor)
{
    revealInAncestors(editor);
    QWidget *target = &editor;
    if (editor.focusPolicy() == Qt::NoFocus) { // a panel: its first field
        for (QWidget *child : editor.findChildren<QWidget *>()) {
            if (child->focusPolicy() != Qt::NoFocus && child->isEnabled()) {
                target = child;
                break;
            }
        }
    }
    target->setFocus(Qt::OtherFocusReason);
    if (auto *spin = qobject_cast<QAbstractSpinBox *>(target))
        spin->selectAll();
    else if (auto *line = qobject_cast<QLineEdit *>(target))
        line->selectAll();
}

} // namespace tolturn
