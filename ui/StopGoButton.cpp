#include "StopGoButton.h"

#include "model/Railway.h"

#include <QEvent>

namespace stellwerk::ui {

namespace {

// Colours of the CS2's own STOP and GO keys, readable with white text in light and dark themes.
const QString stopStyle =
    QStringLiteral("QToolButton { background: #c62828; color: white; font-weight: bold; border-radius: 6px; "
                   "padding: 6px 22px; } QToolButton:pressed { background: #8e1c1c; } "
                   "QToolButton:disabled { background: #9e9e9e; color: #eeeeee; }");
const QString goStyle =
    QStringLiteral("QToolButton { background: #2e7d32; color: white; font-weight: bold; border-radius: 6px; "
                   "padding: 6px 22px; } QToolButton:pressed { background: #1b5e20; }");

} // namespace

StopGoButton::StopGoButton(QWidget* parent) : QToolButton(parent) {
    setObjectName(QStringLiteral("stopGoButton"));
    setToolButtonStyle(Qt::ToolButtonTextOnly);
    setFocusPolicy(Qt::NoFocus); // Space and Escape stop the layout; they must never "click" GO
    QFont large = font();
    large.setPointSizeF(large.pointSizeF() * 1.5);
    large.setBold(true);
    setFont(large);
    connect(this, &QToolButton::clicked, this, &StopGoButton::press);
    refresh();
}

void StopGoButton::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    if (m_railway)
        connect(m_railway, &model::Railway::powerChanged, this, &StopGoButton::refresh);
    refresh();
}

void StopGoButton::stopEverything() {
    if (m_railway)
        m_railway->stop();
}

bool StopGoButton::stops() const {
    const auto power = m_railway ? m_railway->power() : std::nullopt;
    return !power || *power == station::PowerState::Running;
}

void StopGoButton::press() {
    if (!m_railway)
        return;
    if (stops())
        m_railway->stop();
    else
        m_railway->go();
}

void StopGoButton::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QToolButton::changeEvent(event);
}

void StopGoButton::refresh() {
    setEnabled(m_railway != nullptr);
    const bool stopping = stops();
    setText(stopping ? tr("STOP") : tr("GO"));
    setStyleSheet(stopping ? stopStyle : goStyle);
    setToolTip(stopping ? tr("Switch the track power off: every train stops (Space or Escape)")
                        : tr("Switch the track power on again"));
}

} // namespace stellwerk::ui
