// SPDX-License-Identifier: GPL-3.0-or-later
// Answering the modal message boxes a GUI test provokes (an error after a bad file, say).
#pragma once

#include <QApplication>
#include <QMessageBox>
#include <QString>
#include <QTimer>

namespace tolturn::test {

// Closes the next modal message box once it is shown and returns its text through `text`.
inline void closeNextMessageBox(QString *text)
{
    QTimer::singleShot(0, [text] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (box == nullptr) {
            closeNextMessageBox(text); // not shown yet: try again on the next turn of the loop
            return;
        }
        *text = box->text();
        box->accept();
    });
}

} // namespace tolturn::test
