#include "connect/TrafficStatus.h"

#include "connection/ConnectionBuses.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QTimer>

namespace stellwerk::ui {

TrafficStatus::TrafficStatus(QWidget* parent)
    : QWidget(parent), m_text(new QLabel(this)), m_timer(new QTimer(this)) {
    setObjectName(QStringLiteral("trafficStatus"));
    m_text->setObjectName(QStringLiteral("frameCounters"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_text);
    m_timer->setInterval(RefreshMs);
    connect(m_timer, &QTimer::timeout, this, &TrafficStatus::refresh);
    refresh();
}

void TrafficStatus::setBuses(const connection::ConnectionBuses* buses) {
    m_buses = buses;
    if (m_buses)
        m_timer->start();
    else
        m_timer->stop();
    refresh();
}

QString TrafficStatus::text() const {
    return m_text->text();
}

void TrafficStatus::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QWidget::changeEvent(event);
}

void TrafficStatus::refresh() {
    const transport::TransportCounters counters =
        m_buses ? m_buses->stationCounters() : transport::TransportCounters{};
    const QLocale locale;
    m_text->setText(tr("Frames in %1 · out %2")
                        .arg(locale.toString(qulonglong(counters.framesIn)),
                             locale.toString(qulonglong(counters.framesOut))));
    m_text->setToolTip(tr("Frames received from and sent to the station since connecting; "
                          "%1 malformed, %2 dropped, %3 reconnects")
                           .arg(counters.malformed)
                           .arg(counters.dropped)
                           .arg(counters.reconnects));
}

} // namespace stellwerk::ui
