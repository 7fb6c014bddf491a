// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/dialogs/about_dialog.h"

#include "widgets/plot/plot_backend.h"

#include <QDialogButtonBox>
#include <QIcon>
#include <QLabel>
#include <QVBoxLayout>

namespace tolturn {

std::vector<LibraryInfo> applicationLibraries()
{
    std::vector<LibraryInfo> libraries = coreLibraries();
    libraries.push_back(plotBackendInfo());
    return libraries;
}

QString AboutDialog::aboutHtml()
{
    QString rows;
    for (const LibraryInfo &lib : applicationLibraries()) {
        rows += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>")
                    .arg(lib.name.toHtmlEscaped(), lib.version.toHtmlEscaped(), lib.licence.toHtmlEscaped());
    }
    return QStringLiteral("<h2>TolTurn %1</h2>").arg(tolturnVersion()) +
           tr("<p>Tolerance-aware planning of CNC turning: deflection of machine, workpiece and tool, "
              "ISO 286 and ISO 1101 verdicts, and cutting conditions that hold them.</p>"
              "<p>Licensed under the GNU General Public License, version 3 or later (GPL-3.0-or-later). "
              "There is no warranty.</p>") +
           QStringLiteral("<p><b>%1</b></p><table cellspacing='0' cellpadding='3'>"
                          "<tr><th align='left'>%2</th><th align='left'>%3</th><th align='left'>%4</th></tr>%5"
                          "</table>")
               .arg(tr("Built with"), tr("Library"), tr("Version"), tr("Licence"), rows);
}

AboutDialog::AboutDialog(QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("About TolTurn"));
    auto *layout = new QVBoxLayout(this);
    auto *text = new QLabel(aboutHtml(), this);
    text->setObjectName(QStringLiteral("aboutText"));
    text->setTextFormat(Qt::RichText);
    text->setWordWrap(true);
    text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(text);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    setMinimumWidth(520);
}

} // namespace tolturn
