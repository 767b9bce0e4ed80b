#include "connect/ConnectDialog.h"

#include "connect/ConnectionStatus.h"
#include "connect/StationUrlSettings.h"
#include "connection/StationAddress.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace stellwerk::ui {

namespace {

// How a person names an address in the recent list.
QString describeUrl(const QString& url) {
    return ConnectionStatus::describe(connection::StationAddress::endpointOf(url));
}

QRadioButton* radio(QWidget* parent, const char* name) {
    auto* button = new QRadioButton(parent);
    button->setObjectName(QLatin1String(name));
    return button;
}

} // namespace

ConnectDialog::ConnectDialog(const QString& url, QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("connectDialog"));
    createWidgets();
    refreshInterfaces();
    createRecent();
    retranslate();
    setUrl(url);
}

void ConnectDialog::createWidgets() {
    m_recentLabel = new QLabel(this);
    m_recent = new QComboBox(this);
    m_recent->setObjectName(QStringLiteral("recentStations"));
    m_recentLabel->setBuddy(m_recent);
    m_urlLabel = new QLabel(this);
    m_url = new QLineEdit(this);
    m_url->setObjectName(QStringLiteral("stationUrl"));
    m_url->setPlaceholderText(QStringLiteral("udp://192.168.2.5"));
    m_url->setMinimumWidth(m_url->fontMetrics().averageCharWidth() * 40);
    m_urlLabel->setBuddy(m_url);
    m_examples = new QLabel(this);
    m_examples->setObjectName(QStringLiteral("urlExamples"));
    m_examples->setTextFormat(Qt::PlainText);
    m_examples->setForegroundRole(QPalette::PlaceholderText);
    m_furtherLabel = new QLabel(this);
    m_further = new QLineEdit(this);
    m_further->setObjectName(QStringLiteral("furtherBuses"));
    m_further->setPlaceholderText(QStringLiteral("can://socketcan/can1"));
    m_furtherLabel->setBuddy(m_further);
    m_furtherHint = new QLabel(this);
    m_furtherHint->setObjectName(QStringLiteral("furtherBusesHint"));
    m_furtherHint->setForegroundRole(QPalette::PlaceholderText);
    m_furtherHint->setWordWrap(true);
    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("urlError"));
    m_error->setStyleSheet(QStringLiteral("color: #c82c2c"));
    m_error->setWordWrap(true);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_connect = m_buttons->addButton(QString(), QDialogButtonBox::AcceptRole);
    m_connect->setObjectName(QStringLiteral("connectButton"));
    m_connect->setDefault(true);

    auto* recentLine = new QHBoxLayout;
    recentLine->addWidget(m_recentLabel);
    recentLine->addWidget(m_recent, 1);
    auto* address = new QFormLayout;
    address->addRow(m_urlLabel, m_url);
    address->addRow(QString(), m_examples);
    address->addRow(m_furtherLabel, m_further);
    address->addRow(QString(), m_furtherHint);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(recentLine);
    layout->addLayout(createChoices());
    layout->addLayout(address);
    layout->addWidget(m_error);
    layout->addStretch(1);
    layout->addWidget(m_buttons);

    connect(m_url, &QLineEdit::textEdited, this, &ConnectDialog::readUrl);
    connect(m_url, &QLineEdit::textChanged, this, &ConnectDialog::check);
    connect(m_further, &QLineEdit::textChanged, this, &ConnectDialog::check);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ConnectDialog::reject);
}

// One radio button per kind of station, with the fields that kind needs beside it.
QLayout* ConnectDialog::createChoices() {
    m_kinds = new QButtonGroup(this);
    m_simulated = radio(this, "useSimulatedStation");
    m_udp = radio(this, "useUdp");
    m_tcp = radio(this, "useTcp");
    m_can = radio(this, "useCan");
    m_kinds->addButton(m_simulated, int(Kind::Simulated));
    m_kinds->addButton(m_udp, int(Kind::Udp));
    m_kinds->addButton(m_tcp, int(Kind::Tcp));
    m_kinds->addButton(m_can, int(Kind::CanBus));
    m_hostLabel = new QLabel(this);
    m_host = new QLineEdit(this);
    m_host->setObjectName(QStringLiteral("stationHost"));
    m_host->setPlaceholderText(QStringLiteral("192.168.2.5"));
    m_hostLabel->setBuddy(m_host);
    m_interfaceLabel = new QLabel(this);
    m_interface = new QComboBox(this);
    m_interface->setObjectName(QStringLiteral("canInterface"));
    m_interface->setEditable(true);
    m_interface->setMinimumContentsLength(24);
    m_interfaceLabel->setBuddy(m_interface);
    m_refresh = new QPushButton(this);
    m_refresh->setObjectName(QStringLiteral("refreshInterfaces"));

    auto* grid = new QGridLayout;
    grid->addWidget(m_simulated, 0, 0, 1, 4);
    grid->addWidget(m_udp, 1, 0, 1, 4);
    grid->addWidget(m_tcp, 2, 0, 1, 4);
    grid->addWidget(m_hostLabel, 3, 1);
    grid->addWidget(m_host, 3, 2, 1, 2);
    grid->addWidget(m_can, 4, 0, 1, 4);
    grid->addWidget(m_interfaceLabel, 5, 1);
    grid->addWidget(m_interface, 5, 2);
    grid->addWidget(m_refresh, 5, 3);
    grid->setColumnMinimumWidth(0, fontMetrics().averageCharWidth() * 3);
    grid->setColumnStretch(2, 1);

    connect(m_kinds, &QButtonGroup::idClicked, this, [this](int id) { chooseKind(Kind(id)); });
    connect(m_host, &QLineEdit::textEdited, this, &ConnectDialog::composeUrl);
    connect(m_interface, &QComboBox::currentTextChanged, this, &ConnectDialog::composeUrl);
    connect(m_refresh, &QPushButton::clicked, this, &ConnectDialog::refreshInterfaces);
    return grid;
}

// The recent stations, newest first; choosing one fills the dialog with it.
void ConnectDialog::createRecent() {
    m_recent->clear();
    m_recent->addItem(QString());
    for (const QString& url : StationUrlSettings::recent()) {
        const QString shown =
            url.isEmpty() ? describeUrl(url) : describeUrl(url) + QStringLiteral(" — ") + url;
        m_recent->addItem(shown, url);
    }
    m_recent->setEnabled(m_recent->count() > 1);
    connect(m_recent, &QComboBox::activated, this, [this](int index) {
        if (index > 0)
            setUrl(m_recent->itemData(index).toString());
    });
}

void ConnectDialog::refreshInterfaces() {
    const QString typed = m_interface->currentText();
    const bool wasSyncing = std::exchange(m_syncing, true);
    m_interface->clear();
    for (const connection::CanInterfaceChoice& found : connection::availableCanInterfaces()) {
        const QString& name = found.name;
        m_interface->addItem(name, name);
        if (!found.description.isEmpty())
            m_interface->setItemData(m_interface->count() - 1, found.description, Qt::ToolTipRole);
    }
    m_interface->setCurrentText(typed.isEmpty() && m_interface->count() > 0 ? m_interface->itemText(0)
                                                                            : typed);
    m_syncing = wasSyncing;
}

QString ConnectDialog::url() const {
    return m_simulated->isChecked() ? QString() : m_url->text().trimmed();
}

ConnectDialog::Kind ConnectDialog::kind() const {
    return Kind(m_kinds->checkedId());
}

void ConnectDialog::setUrl(const QString& url) {
    m_url->setText(url.trimmed());
    if (url.trimmed().isEmpty())
        chooseKind(Kind::Simulated);
    else
        readUrl();
    check();
}

void ConnectDialog::accept() {
    check();
    if (!m_connect->isEnabled())
        return;
    StationUrlSettings::save(url());
    StationUrlSettings::saveFurtherBuses(furtherBuses());
    QDialog::accept();
}

void ConnectDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ConnectDialog::retranslate() {
    setWindowTitle(tr("Connect to a station"));
    m_recentLabel->setText(tr("&Recent:"));
    m_recent->setItemText(0, m_recent->count() > 1 ? tr("Choose a station used before…") : tr("None yet"));
    m_simulated->setText(tr("&Simulated station (demo layout, no hardware needed)"));
    m_udp->setText(tr("CS2 or CS3 over &UDP (the CAN gateway, ports 15731/15730)"));
    m_tcp->setText(tr("CS2 or CS3 over &TCP (port 15731)"));
    m_hostLabel->setText(tr("&Host:"));
    m_can->setText(tr("CAN &interface (Gleisbox through a CAN adapter)"));
    m_interfaceLabel->setText(tr("&Interface:"));
    m_interface->lineEdit()->setPlaceholderText(tr("plugin/interface, e.g. socketcan/can0"));
    m_refresh->setText(tr("&Look again"));
    m_refresh->setToolTip(tr("List the CAN interfaces Qt's plugins find now"));
    m_urlLabel->setText(tr("&Address:"));
    m_examples->setText(tr("Examples:\n"
                           "udp://192.168.2.5 — a CS2 with its CAN-UDP gateway switched on\n"
                           "tcp://192.168.2.5 — a CS3, or a CS2 over TCP\n"
                           "tcp://127.0.0.1:15731?http=8080 — stellwerk-sim, its pictures on port 8080\n"
                           "can://socketcan/can0 — a Gleisbox through a CAN adapter"));
    m_furtherLabel->setText(tr("Further &buses:"));
    m_furtherHint->setText(tr("Optional: more CAN buses to watch beside the station, such as a USB-CAN "
                              "adapter wired to relay modules; separate several with commas. Their frames "
                              "show in the bus monitor."));
    m_connect->setText(tr("&Connect"));
    check();
}

void ConnectDialog::chooseKind(Kind kind) {
    m_kinds->button(int(kind))->setChecked(true);
    composeUrl();
}

// The fields become the address; what only the address says (ports, bitrate) is kept.
void ConnectDialog::composeUrl() {
    if (m_syncing || kind() == Kind::Simulated) { // the address stays as it was, unused
        check();
        return;
    }
    using Address = connection::StationAddress;
    using Endpoint = connection::StationEndpoint;
    QString url;
    switch (kind()) {
    case Kind::Simulated:
        break;
    case Kind::Udp:
        url = Address::atHost(Endpoint::Kind::Udp, m_host->text(), m_url->text());
        break;
    case Kind::Tcp:
        url = Address::atHost(Endpoint::Kind::Tcp, m_host->text(), m_url->text());
        break;
    case Kind::CanBus:
        url = Address::ofCanInterface(m_interface->currentText());
        break;
    }
    const bool wasSyncing = std::exchange(m_syncing, true);
    m_url->setText(url);
    m_syncing = wasSyncing;
    check();
}

// A typed or given address picks its kind and fills the fields.
void ConnectDialog::readUrl() {
    if (m_syncing)
        return;
    const auto address = connection::StationAddress::read(m_url->text());
    if (!address)
        return;
    const bool wasSyncing = std::exchange(m_syncing, true);
    using Endpoint = connection::StationEndpoint;
    if (address->kind == Endpoint::Kind::Udp || address->kind == Endpoint::Kind::Tcp) {
        (address->kind == Endpoint::Kind::Udp ? m_udp : m_tcp)->setChecked(true);
        m_host->setText(address->host);
    } else if (address->kind == Endpoint::Kind::CanBus) {
        m_can->setChecked(true);
        m_interface->setCurrentText(address->canInterface);
    }
    m_syncing = wasSyncing;
    check();
}

// The address must be readable unless the simulated station is chosen; the reason is shown at once.
void ConnectDialog::check() {
    const Kind chosen = kind();
    const bool simulated = chosen == Kind::Simulated;
    m_url->setEnabled(!simulated);
    m_host->setEnabled(chosen == Kind::Udp || chosen == Kind::Tcp);
    m_interface->setEnabled(chosen == Kind::CanBus);
    m_refresh->setEnabled(chosen == Kind::CanBus);
    QString error;
    if (!simulated) {
        const QString text = m_url->text().trimmed();
        if (text.isEmpty())
            error = tr("Enter the station's address, or use the simulated station.");
        else if (const auto address = connection::StationAddress::read(text); !address)
            error = tr("This address cannot be used: %1").arg(address.error());
    }
    if (error.isEmpty())
        error = furtherBusError();
    m_error->setText(error);
    m_error->setVisible(!error.isEmpty());
    m_connect->setEnabled(error.isEmpty());
}

QStringList ConnectDialog::furtherBuses() const {
    QStringList addresses;
    for (const QString& address : m_further->text().split(QLatin1Char(','), Qt::SkipEmptyParts))
        if (!address.trimmed().isEmpty())
            addresses.append(address.trimmed());
    return addresses;
}

void ConnectDialog::setFurtherBuses(const QStringList& addresses) {
    m_further->setText(addresses.join(QStringLiteral(", ")));
}

// Every further bus must be readable; the station's own address must not be listed again.
QString ConnectDialog::furtherBusError() const {
    for (const QString& address : furtherBuses()) {
        if (const auto read = connection::StationAddress::read(address); !read)
            return tr("The further bus %1 cannot be used: %2").arg(address, read.error());
        if (kind() != Kind::Simulated && address == url())
            return tr("The further bus %1 is the station's own address.").arg(address);
    }
    return {};
}

} // namespace stellwerk::ui
