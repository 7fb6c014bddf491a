// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/dialogs/help_browser.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <map>

namespace tolturn {

namespace {

const QString kHelpRoot = QStringLiteral("qrc:/help/");

} // namespace

HelpBrowser::HelpBrowser(QWidget *parent) : QDialog(parent), m_browser(new QTextBrowser(this))
{
    setObjectName(QStringLiteral("helpBrowser"));
    setWindowTitle(tr("TolTurn User Guide"));
    m_browser->setOpenExternalLinks(true);
    m_browser->setSearchPaths({QStringLiteral(":/help")});
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    QPushButton *contents = buttons->addButton(tr("&Contents"), QDialogButtonBox::ActionRole);
    QPushButton *back = buttons->addButton(tr("&Back"), QDialogButtonBox::ActionRole);
    connect(contents, &QPushButton::clicked, this, [this] { showPage(QStringLiteral("index.html")); });
    connect(back, &QPushButton::clicked, m_browser, &QTextBrowser::backward);
    connect(m_browser, &QTextBrowser::backwardAvailable, back, &QPushButton::setEnabled);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_browser, 1);
    layout->addWidget(buttons);
    resize(640, 560);
    showPage(QStringLiteral("index.html"));
}

void HelpBrowser::showPage(const QString &page)
{
    const QString name = pages().contains(page) ? page : QStringLiteral("index.html");
    m_browser->setSource(QUrl(kHelpRoot + name));
}

QString HelpBrowser::currentPage() const
{
    return m_browser->source().fileName();
}

QString HelpBrowser::pageText() const
{
    return m_browser->toPlainText();
}

QString HelpBrowser::pageForDock(const QString &dockObjectName)
{
    static const std::map<QString, QString> pagesByDock{
        {QStringLiteral("setupDock"), QStringLiteral("setup.html")},
        {QStringLiteral("featureDock"), QStringLiteral("feature.html")},
        {QStringLiteral("tolerancesDock"), QStringLiteral("tolerances.html")},
        {QStringLiteral("deflectionDock"), QStringLiteral("deflection.html")},
        {QStringLiteral("planningDock"), QStringLiteral("planning.html")},
        {QStringLiteral("importDock"), QStringLiteral("import-messages.html")},
        {QStringLiteral("problemsDock"), QStringLiteral("problems.html")},
        {QStringLiteral("measurementsDock"), QStringLiteral("measurements.html")},
        {QStringLiteral("millingDock"), QStringLiteral("milling.html")},
        {QStringLiteral("profileView"), QStringLiteral("drawing.html")},
    };
    const auto it = pagesByDock.find(dockObjectName);
    return it != pagesByDock.end() ? it->second : QStringLiteral("index.html");
}

QStringList HelpBrowser::pages()
{
    return {
        QStringLiteral("index.html"),        QStringLiteral("drawing.html"),         QStringLiteral("setup.html"),
        QStringLiteral("feature.html"),      QStringLiteral("tolerances.html"),      QStringLiteral("deflection.html"),
        QStringLiteral("planning.html"),     QStringLiteral("import-messages.html"), QStringLiteral("problems.html"),
        QStringLiteral("measurements.html"), QStringLiteral("milling.html")};
}

} // namespace tolturn
