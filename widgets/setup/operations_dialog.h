// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/project/project.h"

#include <QDialog>

#include <functional>
#include <vector>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace tolturn {

// The operations (set-ups) of a project (docs/operations.md): the first is the project's own
// set-up and cuts every feature no other names; operations after it are added, removed, renamed
// and given the features they cut here. OK applies them as one undoable edit through `apply`,
// which returns what it refused; the dialog then stays open with the findings.
class OperationsDialog : public QDialog {
    Q_OBJECT
public:
    using Apply = std::function<Diagnostics(const std::vector<Operation> &)>;

    OperationsDialog(const Project &project, Apply apply, QWidget *parent = nullptr);

    [[nodiscard]] const std::vector<Operation> &operations() const { return m_operations; }

    [[nodiscard]] QListWidget *operationList() const { return m_list; }

    [[nodiscard]] QListWidget *featureList() const { return m_features; }

    [[nodiscard]] QLineEdit *nameEdit() const { return m_name; }

    [[nodiscard]] QLabel *messageLabel() const { return m_message; }

    // A new operation after the others: the project's set-up turned end for end, cutting nothing
    // yet; it is selected.
    void addOperation();
    void removeOperation();
    void accept() override;

private:
    void showOperation(int row);
    void featureToggled(int row);
    void refreshList();

    Project m_project;
    Apply m_apply;
    std::vector<Operation> m_operations;
    QListWidget *m_list;
    QListWidget *m_features;
    QLineEdit *m_name;
    QPushButton *m_remove;
    QLabel *m_message;
    bool m_showing = false;
};

} // namespace tolturn
