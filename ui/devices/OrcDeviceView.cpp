#include "devices/OrcDeviceView.h"

#include "common/NotReported.h"
#include "devices/DeviceTableModel.h"
#include "devices/HexText.h"
#include "devices/SignalGrid.h"
#include "orccentral/OrcSession.h"

#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>

namespace stellwerk::ui {
namespace {

using orccentral::OrcDevice;

constexpr std::uint8_t Decoder = 2;
constexpr std::uint8_t Encoder = 3;
constexpr int DecoderOutputs = 8;
constexpr int EncoderInputs = 32;

} // namespace

OrcDeviceView::OrcDeviceView(QWidget* parent)
    : QWidget(parent), m_title(new QLabel(this)), m_details(new QLabel(this)),
      m_signalsLabel(new QLabel(this)), m_signals(new SignalGrid(SignalGrid::Kind::Lamps, this)) {
    setObjectName(QStringLiteral("orcDeviceView"));
    m_details->setObjectName(QStringLiteral("orcDetails"));
    m_signals->setObjectName(QStringLiteral("orcSignals"));
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_details->setWordWrap(true);
    m_signalsLabel->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_title);
    layout->addWidget(m_details);
    layout->addWidget(m_signalsLabel);
    layout->addWidget(m_signals);
    layout->addStretch(1);
}

void OrcDeviceView::setDevice(orccentral::OrcSession* session, std::uint32_t uid) {
    m_uid = uid;
    if (session != m_session)
        attach(session);
    update();
}

void OrcDeviceView::attach(orccentral::OrcSession* session) {
    if (m_session)
        m_session->disconnect(this);
    m_session = session;
    m_confirmed.clear(); // another central: what the old one heard is not its knowledge
    if (!session)
        return;
    connect(session, &orccentral::OrcSession::deviceChanged, this, &OrcDeviceView::update);
    connect(session, &orccentral::OrcSession::inputsChanged, this, &OrcDeviceView::update);
    connect(session, &orccentral::OrcSession::overloadChanged, this, &OrcDeviceView::update);
    connect(session, &orccentral::OrcSession::switchReported, this,
            [this](std::uint16_t target, std::uint8_t position, orccentral::OrcSession::SwitchResult result) {
                if (result == orccentral::OrcSession::SwitchResult::Confirmed)
                    m_confirmed[target] = position;
                else
                    m_confirmed.erase(target); // sent, not confirmed: where its outputs stand is unknown
                update();
            });
}

void OrcDeviceView::update() {
    const OrcDevice* device = m_session ? m_session->device(m_uid) : nullptr;
    m_title->setText(tr("OpenRailCAN device %1").arg(hexText::of(m_uid, 8)));
    m_details->setText(detailsText());
    const bool online = device && device->state == OrcDevice::State::Online;
    if (device && !online)
        m_confirmed.erase(device->busId); // back online, it has confirmed nothing yet
    if (device && device->type == Encoder) {
        m_signalsLabel->setText(tr("Inputs"));
        m_signals->setCount(device->inputCount ? device->inputCount : EncoderInputs);
        m_signals->setStates(online && device->inputCount ? std::optional(device->inputs) : std::nullopt);
    } else if (device && device->type == Decoder) {
        m_signalsLabel->setText(
            tr("Outputs as the decoder last confirmed them (%1 until it confirms a switch)")
                .arg(NotReported::word()));
        m_signals->setCount(DecoderOutputs);
        const auto known = m_confirmed.find(device->busId);
        m_signals->setStates(online && known != m_confirmed.end()
                                 ? std::optional<std::uint32_t>(known->second)
                                 : std::nullopt);
    } else {
        m_signalsLabel->clear();
        m_signals->setCount(0);
    }
}

QString OrcDeviceView::detailsText() const {
    const OrcDevice* device = m_session ? m_session->device(m_uid) : nullptr;
    if (!device)
        return tr("The central no longer knows this device.");
    QString text = tr("%1, bus id %2, version %3.%4")
                       .arg(DeviceTableModel::orcTypeName(device->type), hexText::of(device->busId, 4))
                       .arg(device->version >> 8)
                       .arg(device->version & 0xFF);
    switch (device->state) {
    case OrcDevice::State::Assigning:
        text += QLatin1Char('\n') + tr("Getting its bus id from the central.");
        break;
    case OrcDevice::State::Online:
        text += QLatin1Char('\n') + tr("Online: answers the central's pings.");
        break;
    case OrcDevice::State::Offline:
        text += QLatin1Char('\n') +
                tr("Offline: missed %n ping(s); what it reported is %1.", nullptr, device->missedPings)
                    .arg(NotReported::word());
        break;
    case OrcDevice::State::Unassigned:
        text +=
            QLatin1Char('\n') + tr("Refused: another device has its bus id and it did not take a new one.");
        break;
    }
    if (const QString overloads = overloadText(); !overloads.isEmpty())
        text += QLatin1Char('\n') + overloads;
    return text;
}

QString OrcDeviceView::overloadText() const {
    const OrcDevice* device = m_session->device(m_uid);
    QStringList ports;
    for (const auto& [port, kind] : device->overloads)
        if (kind != 0)
            ports << (port == 0xFF ? tr("the whole device") : tr("output %1").arg(port));
    if (ports.isEmpty())
        return device->type == 0 ? tr("No overload.") : QString();
    return tr("OVERLOAD: %1").arg(ports.join(QStringLiteral(", ")));
}

void OrcDeviceView::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        update();
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
