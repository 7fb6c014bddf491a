// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QString>

class QTextBrowser;

namespace tolturn {

// The user guide shipped with the program (resources/help, compiled in; the .deb also installs it
// under /usr/share/doc/tolturn/user-guide): a page per dock, opened by F1 at the page of the dock
// that has the focus, or by Help > User Guide.
class HelpBrowser : public QDialog {
    Q_OBJECT
public:
    explicit HelpBrowser(QWidget *parent = nullptr);

    // Shows a page of the guide by its file name ("planning.html"); the contents for an unknown one.
    void showPage(const QString &page);
    [[nodiscard]] QString currentPage() const;
    [[nodiscard]] QString pageText() const;

    // The guide's page for a dock (its object name, e.g. "planningDock"); "index.html" for none.
    [[nodiscard]] static QString pageForDock(const QString &dockObjectName);
    // Every page of the guide, contents first.
    [[nodiscard]] static QStringList pages();

private:
    QTextBrowser *m_browser;
};

} // namespace tolturn
