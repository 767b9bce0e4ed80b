#include "stopkeys/StopGoButton.h"

#include "model/Railway.h"

#include <QEvent>
#include <algorithm>

namespace stellwerk::ui {

namespace {

// The CS2's own STOP red, readable with white text in light and dark themes.
const QString stopStyle =
    QStringLiteral("QToolButton { background: #c62828; color: white; font-weight: bold; border-radius: 6px; "
                   "border: 2px solid #8e1c1c; padding: 6px 22px; } "
                   "QToolButton:pressed { background: #8e1c1c; } "
                   "QToolButton:disabled { background: #9e9e9e; color: #eeeeee; border-color: #9e9e9e; }");
// Power off: dark red with amber text and a bright red edge. Nothing about it says "all is well". Its
// thicker edge takes a pixel of the padding, so that every look has the same room around its text.
const QString powerOffStyle = QStringLiteral(
    "QToolButton { background: #4a0d0d; color: #ffe082; font-weight: bold; border-radius: 6px; "
    "border: 3px solid #e53935; padding: 5px 21px; } "
    "QToolButton:pressed { background: #2a0606; }");
// Not reported: grey, still a STOP.
const QString notReportedStyle =
    QStringLiteral("QToolButton { background: #616161; color: white; font-weight: bold; border-radius: 6px; "
                   "border: 2px dashed #bdbdbd; padding: 6px 22px; } "
                   "QToolButton:pressed { background: #424242; }");

} // namespace

StopGoButton::StopGoButton(QWidget* parent) : QToolButton(parent) {
    setObjectName(QStringLiteral("stopGoButton"));
    setToolButtonStyle(Qt::ToolButtonTextOnly);
    setFocusPolicy(Qt::NoFocus); // Space stops the layout; it must never "click" the power back on
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
    if (m_railway) {
        connect(m_railway, &model::Railway::powerChanged, this, &StopGoButton::refresh);
        connect(m_railway, &model::Railway::stateReportedChanged, this, &StopGoButton::refresh);
        connect(m_railway, &QObject::destroyed, this, &StopGoButton::refresh);
    }
    refresh();
}

void StopGoButton::stopEverything() {
    if (m_railway)
        m_railway->stop();
}

StopGoButton::Look StopGoButton::look() const {
    const auto power = m_railway && m_railway->isStateReported() ? m_railway->power() : std::nullopt;
    if (!power)
        return Look::NotReported;
    switch (*power) {
    case station::PowerState::Running:
        return Look::Stop;
    case station::PowerState::Halted:
        return Look::Halted;
    case station::PowerState::Stopped:
        break;
    }
    return Look::PowerOff;
}

bool StopGoButton::stops() const {
    return look() == Look::Stop || look() == Look::NotReported;
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

// As wide as its widest look in the current language: a change of state never moves the keys beside it.
QSize StopGoButton::sizeHint() const {
    QSize hint = QToolButton::sizeHint();
    const auto width = [metrics = fontMetrics()](const QString& text) { // as QToolButton measures it
        return metrics.size(Qt::TextShowMnemonic, text).width();
    };
    int widest = 0;
    for (const Look look : {Look::Stop, Look::PowerOff, Look::Halted, Look::NotReported})
        widest = std::max(widest, width(textOf(look)));
    hint.rwidth() += widest - width(text());
    return hint;
}

QSize StopGoButton::minimumSizeHint() const {
    return sizeHint();
}

QString StopGoButton::textOf(Look look) {
    switch (look) {
    case Look::Stop:
        return tr("STOP");
    case Look::PowerOff:
        return tr("TRACK POWER OFF · press to switch on");
    case Look::Halted:
        return tr("TRAINS HALTED · press to go on");
    case Look::NotReported:
        break;
    }
    return tr("STOP · power not reported");
}

void StopGoButton::refresh() {
    setEnabled(m_railway != nullptr);
    const Look shown = m_railway ? look() : Look::Stop;
    setText(textOf(shown));
    switch (shown) {
    case Look::Stop:
        setStyleSheet(stopStyle);
        setToolTip(tr("Track power is on. Press to switch it off: every train stops (Space)"));
        break;
    case Look::PowerOff:
        setStyleSheet(powerOffStyle);
        setToolTip(tr("The layout is stopped: the station switched the track power off. Press to switch it "
                      "on again (GO); trains resume their speeds."));
        break;
    case Look::Halted:
        setStyleSheet(powerOffStyle);
        setToolTip(tr("Every train was halted; the track still has power. Press to let them go on (GO)."));
        break;
    case Look::NotReported:
        setStyleSheet(notReportedStyle);
        setToolTip(tr("The station has not reported the track power (silent, reconnecting or not yet "
                      "said). Press to switch it off anyway (Space)."));
        break;
    }
    updateGeometry();
}

} // namespace stellwerk::ui
