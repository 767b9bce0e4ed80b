#include "common/SideBySide.h"

#include <QBoxLayout>
#include <QEvent>
#include <QSplitter>
#include <QWidget>

namespace stellwerk::ui {

SideBySide::SideBySide(QWidget* panel, int width) : QObject(panel), m_width(width) {
    panel->installEventFilter(this);
}

void SideBySide::arrange(QWidget* panel, QSplitter* parts, int width) {
    auto* side = new SideBySide(panel, width);
    side->m_splitter = parts;
    side->follow(panel->width());
}

void SideBySide::arrange(QWidget* panel, QBoxLayout* parts, int width) {
    auto* side = new SideBySide(panel, width);
    side->m_layout = parts;
    side->follow(panel->width());
}

bool SideBySide::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Resize)
        follow(static_cast<QWidget*>(watched)->width());
    return QObject::eventFilter(watched, event);
}

void SideBySide::follow(int panelWidth) {
    const bool wide = panelWidth >= m_width;
    if (m_splitter && m_splitter->orientation() != (wide ? Qt::Horizontal : Qt::Vertical))
        m_splitter->setOrientation(wide ? Qt::Horizontal : Qt::Vertical);
    const QBoxLayout::Direction direction = wide ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom;
    if (m_layout && m_layout->direction() != direction)
        m_layout->setDirection(direction);
}

} // namespace stellwerk::ui
