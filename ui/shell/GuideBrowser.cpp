#include "shell/GuideBrowser.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace stellwerk::ui {

QString GuideBrowser::startPage() {
    const QStringList candidates{QCoreApplication::applicationDirPath() +
                                     QStringLiteral("/../share/doc/stellwerk/guide/README.md"),
                                 QStringLiteral(STELLWERK_SOURCE_DIR "/docs/guide/README.md")};
    for (const QString& candidate : candidates)
        if (QFileInfo::exists(candidate))
            return QDir::cleanPath(QFileInfo(candidate).absoluteFilePath());
    return {};
}

GuideBrowser::GuideBrowser(const QString& page, QWidget* parent)
    : QDialog(parent), m_browser(new QTextBrowser(this)) {
    setObjectName(QStringLiteral("guideBrowser"));
    setWindowTitle(tr("Stellwerk user guide"));
    setAttribute(Qt::WA_DeleteOnClose);
    m_browser->setObjectName(QStringLiteral("guideText"));
    m_browser->setOpenExternalLinks(true);
    m_browser->setSource(QUrl::fromLocalFile(page), QTextDocument::MarkdownResource);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* back = buttons->addButton(tr("&Back"), QDialogButtonBox::ActionRole);
    QPushButton* home = buttons->addButton(tr("&Contents"), QDialogButtonBox::ActionRole);
    back->setEnabled(false);
    connect(m_browser, &QTextBrowser::backwardAvailable, back, &QPushButton::setEnabled);
    connect(back, &QPushButton::clicked, m_browser, &QTextBrowser::backward);
    connect(home, &QPushButton::clicked, m_browser, &QTextBrowser::home);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_browser, 1);
    layout->addWidget(buttons);
    const QScreen* screen = parent ? parent->screen() : QGuiApplication::primaryScreen();
    if (screen)
        resize(readableSize(screen->availableGeometry().size()));
}

QSize GuideBrowser::readableSize(const QSize& available) {
    const QSize least(900, 650);
    return (available * 2 / 3).expandedTo(least).boundedTo(available);
}

void GuideBrowser::showGuide(QWidget* parent) {
    const QString page = startPage();
    if (page.isEmpty()) {
        QMessageBox::information(parent, tr("Stellwerk user guide"),
                                 tr("The user guide is not installed here. It is in the folder docs/guide "
                                    "of Stellwerk's sources, and after installing in "
                                    "share/doc/stellwerk/guide."));
        return;
    }
    auto* browser = new GuideBrowser(page, parent);
    browser->show();
}

} // namespace stellwerk::ui
