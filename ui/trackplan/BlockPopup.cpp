#include "trackplan/BlockPopup.h"

#include <QGuiApplication>
#include <QLabel>
#include <QScreen>
#include <QTextDocument>
#include <QVBoxLayout>
#include <algorithm>

namespace stellwerk::ui {
namespace {

constexpr int MaximumWidth = 480; // a line of about 70 characters: the ways read as sentences

} // namespace

BlockPopup::BlockPopup(QWidget* parent) : QFrame(parent, Qt::Popup) {
    setObjectName(QStringLiteral("blockPopup"));
    setFrameShape(QFrame::StyledPanel);
    // The popup takes the keys while it is open: with the focus on it, Space and the extra STOP key still
    // stop the layout (EmergencyStopKeys looks at the focus widget), and Escape closes it (QWidget's own).
    setFocusPolicy(Qt::StrongFocus);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("blockDescription"));
    m_text->setTextFormat(Qt::RichText);
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(10, 8, 10, 8);
    layout->addWidget(m_text);
}

void BlockPopup::showText(const QString& html, QPoint globalPosition) {
    m_text->setText(html);
    m_text->setMaximumWidth(MaximumWidth);
    adjustSize();
    QRect shown(globalPosition, size());
    if (const QScreen* screen = QGuiApplication::screenAt(globalPosition)) {
        const QRect room = screen->availableGeometry();
        shown.moveRight(std::min(shown.right(), room.right()));
        shown.moveBottom(std::min(shown.bottom(), room.bottom()));
        shown.moveTopLeft(QPoint(std::max(shown.left(), room.left()), std::max(shown.top(), room.top())));
    }
    move(shown.topLeft());
    show();
    setFocus(Qt::PopupFocusReason);
}

QString BlockPopup::plainText() const {
    QTextDocument document;
    document.setHtml(m_text->text());
    return document.toPlainText();
}

} // namespace stellwerk::ui
