#include "model/RailwayDevices.h"

#include "orccentral/OrcSession.h"
#include "romodule/RoModuleSession.h"

#include <algorithm>
#include <utility>

namespace stellwerk::model {

namespace {

using romodule::RoModuleSession;

std::optional<int> positionOf(const OrcOutput& output, std::uint8_t pos) {
    return output.output ? int(pos >> *output.output & 1) : int(pos);
}

bool bit(std::uint32_t value, int numberFrom1) {
    return numberFrom1 >= 1 && numberFrom1 <= 32 && (value >> (numberFrom1 - 1) & 1);
}

} // namespace

RailwayDevices::RailwayDevices(Railway& railway, DeviceBindings bindings, QObject* parent)
    : QObject(parent), railway_(railway), bindings_(std::move(bindings)) {
    railway_.setDeviceAccessories(this);
    connect(&railway_, &Railway::stateReportedChanged, this, [this](bool reported) {
        if (reported)
            refresh(); // the station's loss made every item "not reported"; the devices still know
    });
}

RailwayDevices::~RailwayDevices() {
    railway_.setDeviceAccessories(nullptr);
}

void RailwayDevices::setSessions(orccentral::OrcSession* orc, const std::vector<RoModuleSession*>& modules) {
    if (orc_)
        orc_->disconnect(this);
    for (const auto& module : modules_)
        if (module)
            module->disconnect(this);
    if (orc != orc_.data())
        decoderPositions_.clear(); // a new central: what the old one heard is not its knowledge
    orc_ = orc;
    modules_.assign(modules.begin(), modules.end());
    finish([this](const Pending& p) { return !p.session || !holds(p.session.data()); },
           QStringLiteral("the device's bus went away"));
    if (orc_)
        watchOrc();
    for (RoModuleSession* module : modules)
        watchModule(module);
    refresh();
}

void RailwayDevices::setBindings(DeviceBindings bindings) {
    const DeviceBindings old = std::exchange(bindings_, std::move(bindings));
    finish([this](const Pending& p) { return !drives(p.accessory); },
           QStringLiteral("no device switches it any more"));
    for (const AccessoryBinding& binding : old.accessories)
        if (!drives(binding.accessory))
            railway_.reportDevicePosition(binding.accessory, std::nullopt);
    for (const ContactBinding& binding : old.contacts)
        if (!lights(binding.contact))
            railway_.reportDeviceContact(binding.contact, std::nullopt);
    refresh();
    emit bindingsChanged();
}

// Whether `session` is one of the sessions there are now.
bool RailwayDevices::holds(const QObject* session) const {
    return session == orc_.data() || std::any_of(modules_.begin(), modules_.end(),
                                                 [session](const auto& m) { return m.data() == session; });
}

bool RailwayDevices::drives(std::int64_t accessory) const {
    return bindings_.accessory(accessory) != nullptr;
}

bool RailwayDevices::lights(ContactKey contact) const {
    return bindings_.contact(contact) != nullptr;
}

void RailwayDevices::switchTo(std::int64_t accessory, int position,
                              std::function<void(const QString&)> done) {
    const AccessoryBinding* binding = bindings_.accessory(accessory);
    QString refused;
    if (!binding)
        refused = QStringLiteral("no device switches it");
    else if (position != 0 && position != 1)
        refused = QStringLiteral("a device output has positions 0 and 1 only");
    else if (const auto* relay = std::get_if<RoRelay>(&binding->output))
        refused = switchRelay(*relay, position);
    else
        refused = switchOrc(std::get<OrcOutput>(binding->output), position);
    if (!refused.isEmpty())
        return done(refused);
    QObject* session = orc_.data();
    if (const auto* relay = std::get_if<RoRelay>(&binding->output))
        session = module(relay->module);
    pending_.push_back({accessory, position, std::move(done), session});
}

// Empty when the switching went out; else why not.
QString RailwayDevices::switchRelay(const RoRelay& relay, int position) {
    RoModuleSession* session = module(relay.module);
    if (!session)
        return QStringLiteral("RO module \"%1\" is not connected").arg(relay.module);
    if (!session->setOutput(relay.relay, position == 1))
        return session->state() == RoModuleSession::State::Offline
                   ? QStringLiteral("RO module \"%1\" is offline").arg(relay.module)
                   : QStringLiteral("RO module \"%1\" has no relay %2").arg(relay.module).arg(relay.relay);
    return {};
}

QString RailwayDevices::switchOrc(const OrcOutput& output, int position) {
    if (!orc_)
        return QStringLiteral("the OpenRailCAN central is not running");
    const orccentral::OrcDevice* device = orc_->deviceAt(output.target);
    if (device && device->state != orccentral::OrcDevice::State::Online)
        return QStringLiteral("OpenRailCAN decoder 0x%1 is offline")
            .arg(output.target, 4, 16, QLatin1Char('0'));
    std::uint8_t pos = std::uint8_t(position);
    if (output.output) {
        const std::uint8_t mask = std::uint8_t(1u << *output.output);
        const std::uint8_t known =
            decoderPositions_.count(output.target) ? decoderPositions_[output.target] : 0;
        pos = std::uint8_t(position ? known | mask : known & ~mask);
    }
    orc_->switchOutputs(output.target, pos);
    return {};
}

void RailwayDevices::watchOrc() {
    using orccentral::OrcSession;
    connect(orc_, &OrcSession::switchReported, this,
            [this](std::uint16_t target, std::uint8_t position, OrcSession::SwitchResult result) {
                orcSwitched(target, position, result == OrcSession::SwitchResult::Confirmed);
            });
    connect(
        orc_, &OrcSession::inputsChanged, this,
        [this](std::uint16_t encoder, std::uint32_t inputs, std::uint32_t) { orcInputs(encoder, inputs); });
    connect(orc_, &OrcSession::deviceChanged, this, &RailwayDevices::orcDeviceChanged);
}

// A decoder that is not online may lose its outputs (powered off, reset); what it confirmed before is
// forgotten, so that its articles stay "not reported" until it confirms a switching again.
void RailwayDevices::orcDeviceChanged(std::uint32_t uid) {
    const orccentral::OrcDevice* device = orc_ ? orc_->device(uid) : nullptr;
    if (device && device->state != orccentral::OrcDevice::State::Online)
        decoderPositions_.erase(device->busId);
    refresh();
}

void RailwayDevices::watchModule(RoModuleSession* module) {
    const QString name = QString::fromStdString(module->profile().name);
    connect(module, &RoModuleSession::outputsChanged, this,
            [this, name](std::uint32_t outputs) { moduleOutputs(name, outputs); });
    connect(module, &RoModuleSession::outputsFailed, this,
            [this, name](std::uint32_t relays, const QString& why) { moduleFailed(name, relays, why); });
    connect(module, &RoModuleSession::inputsChanged, this,
            [this, name](std::uint32_t inputs, std::uint32_t) { moduleInputs(name, inputs); });
    connect(module, &RoModuleSession::stateChanged, this, &RailwayDevices::refresh);
}

// A confirmed Pos is the decoder's state. After an unconfirmed one the decoder may have switched or not: its
// articles are "not reported", and the switching waiting for it did not reach a confirmed position.
void RailwayDevices::orcSwitched(std::uint16_t target, std::uint8_t position, bool confirmed) {
    if (confirmed)
        decoderPositions_[target] = position;
    else
        decoderPositions_.erase(target);
    for (const AccessoryBinding& binding : bindings_.accessories)
        if (const auto* output = std::get_if<OrcOutput>(&binding.output);
            output && output->target == target) {
            railway_.reportDevicePosition(binding.accessory,
                                          confirmed ? positionOf(*output, position) : std::optional<int>());
            finish([&](const Pending& p) { return p.accessory == binding.accessory; },
                   confirmed ? QString() : QStringLiteral("sent, but the decoder did not confirm it"));
        }
}

void RailwayDevices::orcInputs(std::uint16_t encoder, std::uint32_t inputs) {
    const orccentral::OrcDevice* device = orc_ ? orc_->deviceAt(encoder) : nullptr;
    if (!device)
        return;
    for (const ContactBinding& binding : bindings_.contacts)
        if (const auto* input = std::get_if<OrcInput>(&binding.input);
            input && input->encoderUid == device->uid)
            railway_.reportDeviceContact(binding.contact, bool(inputs >> input->input & 1));
}

void RailwayDevices::moduleOutputs(const QString& module, std::uint32_t outputs) {
    for (const AccessoryBinding& binding : bindings_.accessories) {
        const auto* relay = std::get_if<RoRelay>(&binding.output);
        if (!relay || relay->module != module)
            continue;
        const int position = bit(outputs, relay->relay) ? 1 : 0;
        railway_.reportDevicePosition(binding.accessory, position);
        finish([&](const Pending& p) { return p.accessory == binding.accessory && p.position == position; },
               {});
    }
}

void RailwayDevices::moduleFailed(const QString& module, std::uint32_t relays, const QString& why) {
    for (const AccessoryBinding& binding : bindings_.accessories)
        if (const auto* relay = std::get_if<RoRelay>(&binding.output);
            relay && relay->module == module && bit(relays, relay->relay))
            finish([&](const Pending& p) { return p.accessory == binding.accessory; },
                   QStringLiteral("RO module \"%1\" did not switch relay %2: %3")
                       .arg(module)
                       .arg(relay->relay)
                       .arg(why));
}

void RailwayDevices::moduleInputs(const QString& module, std::uint32_t inputs) {
    for (const ContactBinding& binding : bindings_.contacts)
        if (const auto* input = std::get_if<RoInput>(&binding.input); input && input->module == module)
            railway_.reportDeviceContact(binding.contact, bit(inputs, input->input));
}

// Every bound item as the sessions know it now: not reported where a session is gone or offline.
void RailwayDevices::refresh() {
    for (const AccessoryBinding& binding : bindings_.accessories) {
        if (const auto* relay = std::get_if<RoRelay>(&binding.output))
            railway_.reportDevicePosition(binding.accessory, relayPosition(*relay));
        else
            railway_.reportDevicePosition(binding.accessory,
                                          orcPosition(std::get<OrcOutput>(binding.output)));
    }
    for (const ContactBinding& binding : bindings_.contacts) {
        if (const auto* input = std::get_if<RoInput>(&binding.input))
            railway_.reportDeviceContact(binding.contact, roInput(*input));
        else
            railway_.reportDeviceContact(binding.contact, orcInput(std::get<OrcInput>(binding.input)));
    }
}

std::optional<int> RailwayDevices::orcPosition(const OrcOutput& output) const {
    const auto known = decoderPositions_.find(output.target);
    if (!orc_ || known == decoderPositions_.end())
        return std::nullopt;
    const orccentral::OrcDevice* device = orc_->deviceAt(output.target);
    if (device && device->state != orccentral::OrcDevice::State::Online)
        return std::nullopt;
    return positionOf(output, known->second);
}

std::optional<int> RailwayDevices::relayPosition(const RoRelay& relay) const {
    const RoModuleSession* session = module(relay.module);
    if (!session || session->state() != RoModuleSession::State::Online || !session->outputs())
        return std::nullopt;
    return bit(*session->outputs(), relay.relay) ? 1 : 0;
}

std::optional<bool> RailwayDevices::orcInput(const OrcInput& input) const {
    const orccentral::OrcDevice* device = orc_ ? orc_->device(input.encoderUid) : nullptr;
    if (!device || device->state != orccentral::OrcDevice::State::Online || device->inputCount == 0)
        return std::nullopt;
    return bool(device->inputs >> input.input & 1);
}

std::optional<bool> RailwayDevices::roInput(const RoInput& input) const {
    const RoModuleSession* session = module(input.module);
    if (!session || session->state() != RoModuleSession::State::Online || !session->inputs())
        return std::nullopt;
    return bit(*session->inputs(), input.input);
}

// Ends the switchings `which` picks, in the order they were asked; `done` may start new ones.
void RailwayDevices::finish(const std::function<bool(const Pending&)>& which, const QString& failure) {
    std::vector<Pending> ended;
    const auto firstEnded =
        std::stable_partition(pending_.begin(), pending_.end(), [&](const Pending& p) { return !which(p); });
    std::move(firstEnded, pending_.end(), std::back_inserter(ended));
    pending_.erase(firstEnded, pending_.end());
    for (Pending& pending : ended)
        pending.done(failure);
}

RoModuleSession* RailwayDevices::module(const QString& name) const {
    const std::string wanted = name.toStdString();
    for (const auto& module : modules_)
        if (module && module->profile().name == wanted)
            return module.data();
    return nullptr;
}

} // namespace stellwerk::model
