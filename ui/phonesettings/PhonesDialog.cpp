#include "phonesettings/PhonesDialog.h"

#include "phones/PhoneServers.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QVBoxLayout>

namespace stellwerk::ui {

PhonesDialog::PhonesDialog(phones::PhoneServers& servers, QWidget* parent)
    : QDialog(parent), m_servers(servers) {
    setObjectName(QStringLiteral("phonesDialog"));
    setWindowTitle(tr("Phones and Tablets"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Phones and tablets drive the layout as throttles: the Z21 app and the "
                                "WLANmaus through the Z21 server, Engine Driver and WiThrottle through the "
                                "WiThrottle server."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    const phones::PhoneSettings& now = servers.settings();
    m_z21 = addServer(QStringLiteral("z21"), tr("Z21 server (Z21 app, WLANmaus)"), now.z21, now.z21Listen);
    m_withrottle =
        addServer(QStringLiteral("withrottle"), tr("WiThrottle server (Engine Driver, WiThrottle)"),
                  now.withrottle, now.withrottleListen);
    // The allowed phones take a line of their own: a few addresses are long.
    m_clients = new QLineEdit(phones::PhoneSettings::clientsText(now.allowedClients), this);
    m_clients->setObjectName(QStringLiteral("allowedClients"));
    m_clients->setPlaceholderText(tr("every phone in the network"));
    auto* clientsLabel = new QLabel(tr("Only these phones (addresses):"), this);
    clientsLabel->setBuddy(m_clients);
    layout->addWidget(clientsLabel);
    layout->addWidget(m_clients);
    // Wide enough for two addresses and the longest label beside its field.
    setMinimumWidth(fontMetrics().averageCharWidth() * 64);
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("phonesProblem"));
    m_problem->setWordWrap(true);
    m_problem->setVisible(false);
    layout->addWidget(m_problem);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &PhonesDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &PhonesDialog::reject);
    layout->addWidget(buttons);
}

PhonesDialog::ServerFields PhonesDialog::addServer(const QString& name, const QString& title, bool on,
                                                   const phones::ListenAddress& listen) {
    auto* box = new QGroupBox(this);
    auto* form = new QFormLayout(box);
    ServerFields fields;
    fields.on = new QCheckBox(title, box);
    fields.on->setObjectName(name + QStringLiteral("On"));
    fields.on->setChecked(on);
    form->addRow(fields.on);
    fields.address = new QLineEdit(box);
    fields.address->setObjectName(name + QStringLiteral("Address"));
    fields.address->setPlaceholderText(tr("all network interfaces"));
    if (listen.address != QHostAddress(QHostAddress::Any))
        fields.address->setText(listen.address.toString());
    form->addRow(tr("Listen on address:"), fields.address);
    fields.port = new QSpinBox(box);
    fields.port->setObjectName(name + QStringLiteral("Port"));
    fields.port->setRange(1, 65535);
    fields.port->setValue(listen.port);
    form->addRow(tr("Port:"), fields.port);
    layout()->addWidget(box);
    return fields;
}

std::optional<phones::ListenAddress> PhonesDialog::listenOf(const ServerFields& fields) {
    phones::ListenAddress listen{QHostAddress::Any, quint16(fields.port->value())};
    const QString address = fields.address->text().trimmed();
    if (!address.isEmpty() && !listen.address.setAddress(address)) {
        m_problem->setText(tr("\"%1\" is not a network address of this computer (for example 192.168.1.20); "
                              "leave it empty to listen on all of them.")
                               .arg(address));
        return std::nullopt;
    }
    return listen;
}

std::optional<phones::PhoneSettings> PhonesDialog::chosen() {
    phones::PhoneSettings settings;
    settings.z21 = m_z21.on->isChecked();
    settings.withrottle = m_withrottle.on->isChecked();
    const auto z21 = listenOf(m_z21);
    const auto withrottle = z21 ? listenOf(m_withrottle) : std::nullopt;
    const auto clients = phones::PhoneSettings::parseClients(m_clients->text());
    if (z21 && withrottle && !clients)
        m_problem->setText(tr("The allowed phones must be network addresses, separated by commas "
                              "(for example 192.168.1.30, 192.168.1.31)."));
    m_problem->setVisible(!z21 || !withrottle || !clients);
    if (!z21 || !withrottle || !clients)
        return std::nullopt;
    settings.z21Listen = *z21;
    settings.withrottleListen = *withrottle;
    settings.allowedClients = *clients;
    return settings;
}

void PhonesDialog::accept() {
    const auto settings = chosen();
    if (!settings)
        return;
    const QStringList problems = m_servers.change(*settings);
    if (!problems.isEmpty()) {
        m_problem->setText(tr("Could not start: %1. Another program may use the port; choose another one.")
                               .arg(problems.join(QStringLiteral("; "))));
        m_problem->setVisible(true);
        return;
    }
    QDialog::accept();
}

} // namespace stellwerk::ui
