#include "common/PowerStatus.h"

#include "common/NotReported.h"
#include "common/StatusDot.h"
#include "model/Railway.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>

namespace stellwerk::ui {

namespace {

QColor powerColour(std::optional<station::PowerState> power) {
    if (!power)
        return StatusDot::Unknown;
    switch (*power) {
    case station::PowerState::Running:
        return StatusDot::Running;
    case station::PowerState::Halted:
        return StatusDot::Halted;
    case station::PowerState::Stopped:
        break;
    }
    return StatusDot::Stopped;
}

} // namespace

PowerStatus::PowerStatus(QWidget* parent)
    : QWidget(parent), m_lamp(new QLabel(this)), m_text(new QLabel(this)) {
    setObjectName(QStringLiteral("powerStatus"));
    m_lamp->setObjectName(QStringLiteral("powerLamp"));
    m_text->setObjectName(QStringLiteral("trackPower"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_lamp);
    layout->addWidget(m_text, 1);
    refresh();
}

void PowerStatus::setRailway(const model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    if (m_railway) {
        connect(m_railway, &model::Railway::powerChanged, this, &PowerStatus::refresh);
        connect(m_railway, &model::Railway::stateReportedChanged, this, &PowerStatus::refresh);
        connect(m_railway, &QObject::destroyed, this, &PowerStatus::refresh);
    }
    refresh();
}

QString PowerStatus::text() const {
    return m_text->text();
}

QString PowerStatus::powerText(const model::Railway* railway) {
    if (!railway)
        return tr("No station connected");
    if (!railway->isStateReported())
        return tr("Track power: not reported");
    const std::optional<station::PowerState> power = railway->power();
    if (!power)
        return tr("Track power: not reported yet");
    switch (*power) {
    case station::PowerState::Running:
        return tr("Track power: on, trains may run");
    case station::PowerState::Halted:
        return tr("Track power: on, every train halted");
    case station::PowerState::Stopped:
        break;
    }
    return tr("Track power: off (stop)");
}

void PowerStatus::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QWidget::changeEvent(event);
}

void PowerStatus::refresh() {
    const int size = m_text->fontMetrics().height() * 3 / 4;
    const bool reported = m_railway && m_railway->isStateReported();
    const QColor colour = powerColour(reported ? m_railway->power() : std::nullopt);
    m_lamp->setPixmap(StatusDot::icon(colour, size).pixmap(size, size));
    m_text->setText(powerText(m_railway));
    m_text->setEnabled(reported && m_railway->power().has_value()); // greyed while not reported
    setToolTip(NotReported::applies(m_railway) ? NotReported::reason() : QString());
}

} // namespace stellwerk::ui
