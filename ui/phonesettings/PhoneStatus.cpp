#include "phonesettings/PhoneStatus.h"

#include "phones/PhoneServers.h"

#include <QEvent>

namespace stellwerk::ui {

PhoneStatus::PhoneStatus(QWidget* parent) : QLabel(parent) {
    setObjectName(QStringLiteral("phoneStatus"));
    setVisible(false);
}

void PhoneStatus::setPhoneServers(phones::PhoneServers* servers) {
    if (m_servers)
        m_servers->disconnect(this);
    m_servers = servers;
    if (servers)
        connect(servers, &phones::PhoneServers::clientsChanged, this, &PhoneStatus::refresh);
    refresh();
}

void PhoneStatus::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QLabel::changeEvent(event);
}

void PhoneStatus::refresh() {
    const bool running = m_servers && m_servers->running();
    setVisible(running);
    if (!running)
        return;
    const QStringList clients = m_servers->clients();
    setText(tr("Phones: %1").arg(clients.size()));
    setToolTip(clients.isEmpty() ? tr("No phone or tablet is connected.")
                                 : tr("Connected:\n%1").arg(clients.join(QLatin1Char('\n'))));
}

} // namespace stellwerk::ui
