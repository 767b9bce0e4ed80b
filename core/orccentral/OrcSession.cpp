#include "orccentral/OrcSession.h"

#include "bus/Bus.h"
#include "orc/Codec.h"
#include "transport/Transport.h"

#include <utility>

namespace stellwerk::orccentral {

namespace {
template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

constexpr std::uint8_t WholeDevice = 0xFF;
} // namespace

OrcSession::OrcSession(bus::Bus& bus, Settings settings, QObject* parent)
    : QObject(parent), bus_(bus), settings_(std::move(settings)), registry_(settings_.busId) {
    for (const std::uint16_t id : settings_.reservedBusIds)
        registry_.reserve(id);
    pingClock_.setInterval(settings_.timing.pingPeriod);
    connect(&pingClock_, &QTimer::timeout, this, &OrcSession::tick);
    bus_.subscribe(busreading::Protocol::Orc, this,
                   [this](const std::vector<can::CanFrame>& frames) { receive(frames); });
}

OrcSession::~OrcSession() = default;

void OrcSession::start() {
    find();
    for (const OrcDevice& device : registry_.devices())
        send(orc::Ping{me(), device.uid});
    pingClock_.start();
}

void OrcSession::find() {
    send(orc::Find{me(), 0}); // DB2-5 = 0: any unregistered device (notes A3.2, Decision)
}

void OrcSession::switchOutputs(std::uint16_t target, std::uint8_t position) {
    send(orc::DecoderSwitch{me(), false, target, position});
    auto timer = std::unique_ptr<QTimer>(startTimer([this, target] { switchTimedOut(target); }));
    switches_[target] = {position, std::move(timer)};
}

void OrcSession::queryEncoder(std::uint16_t encoder) {
    send(orc::EncoderQuery{me(), false, encoder});
    queryTries_.try_emplace(encoder, 0);
    queryTimers_[encoder].reset(startTimer([this, encoder] { queryTimedOut(encoder); }));
}

void OrcSession::setPower(bool on) {
    if (on)
        send(orc::AllOn{me(), orc::Target::all()});
    else
        send(orc::AllOff{me(), orc::Target::all()});
    powerOn_ = on;
    emit powerChanged(on, false);
}

void OrcSession::emergencyStop() {
    send(orc::LocoStop{me(), orc::Target::all()});
    emit emergencyStopped(false);
}

const OrcDevice* OrcSession::device(std::uint32_t uid) const {
    for (const OrcDevice& d : registry_.devices())
        if (d.uid == uid)
            return &d;
    return nullptr;
}

const OrcDevice* OrcSession::deviceAt(std::uint16_t busId) const {
    for (const OrcDevice& d : registry_.devices())
        if (d.busId == busId)
            return &d;
    return nullptr;
}

void OrcSession::receive(const std::vector<can::CanFrame>& frames) {
    for (const can::CanFrame& frame : frames)
        handle(orc::decode(frame));
}

void OrcSession::handle(const orc::Message& message) {
    std::visit(Overloaded{
                   [this](const orc::PingAnswer& m) { announced(m.from, m.uid, m.version); },
                   [this](const orc::FindAnswer& m) { announced(m.from, m.uid, m.version); },
                   [this](const orc::AssignBusId& m) { assigned(m); },
                   [this](const orc::EncoderStatus& m) { encoderStatus(m); },
                   [this](const orc::DecoderSwitch& m) { decoderAck(m); },
                   [this](const orc::Overload& m) { overload(m); },
                   [this](const orc::AllOff& m) {
                       if (m.target.kind == orc::Target::Kind::All && std::exchange(powerOn_, false))
                           emit powerChanged(false, true);
                   },
                   [this](const orc::AllOn& m) {
                       if (m.target.kind == orc::Target::Kind::All && !std::exchange(powerOn_, true))
                           emit powerChanged(true, true);
                   },
                   [this](const orc::LocoStop& m) {
                       if (m.target.kind == orc::Target::Kind::All)
                           emit emergencyStopped(true);
                   },
                   [this](const orc::Unknown&) { ++unreadable_; },
                   [](const auto&) {},
               },
               message);
}

// A device says it is there (a ping answer, asked or not, or the extension's answer to Find), from the bus
// id it uses now. Known under that id: online. Otherwise it gets the id the registry gives its UID.
void OrcSession::announced(const orc::Origin& from, std::uint32_t uid, std::uint16_t version) {
    const std::optional<std::uint16_t> wanted = registry_.busIdFor(uid);
    if (!wanted)
        return;
    OrcDevice& device = registry_.enter(uid, *wanted, from.type);
    device.version = version;
    if (*wanted == from.busId) {
        goesOnline(device);
        return;
    }
    if (device.state == OrcDevice::State::Assigning && assignTimers_.count(uid))
        return; // already asked; its answer or the timeout decides
    device.state = OrcDevice::State::Assigning;
    assignTries_[uid] = 0;
    send(orc::AssignBusId{me(), false, uid, *wanted});
    assignTimers_[uid].reset(startTimer([this, uid] { assignTimedOut(uid); }));
    emit deviceChanged(uid);
}

void OrcSession::assigned(const orc::AssignBusId& answer) {
    OrcDevice* device = registry_.byUid(answer.uid);
    if (!answer.answer || !device || answer.busId != device->busId || answer.from.busId != device->busId)
        return;
    assignTimers_.erase(answer.uid);
    goesOnline(*device);
}

void OrcSession::goesOnline(OrcDevice& device) {
    device.missedPings = 0;
    device.pingOutstanding = false;
    const bool changed = device.state != OrcDevice::State::Online;
    device.state = OrcDevice::State::Online;
    if (!changed)
        return;
    const std::uint32_t uid = device.uid;
    const std::uint16_t busId = device.busId;
    const bool encoder = device.type == std::uint8_t(orc::DeviceType::CanEncoder);
    emit deviceChanged(uid);
    if (encoder)
        queryEncoder(busId); // notes A3.5: query every known encoder after connecting
}

void OrcSession::encoderStatus(const orc::EncoderStatus& status) {
    queryTimers_.erase(status.encoder);
    queryTries_.erase(status.encoder);
    OrcDevice* device = registry_.byBusId(status.encoder);
    std::uint32_t before = 0;
    if (device) {
        before = device->inputs;
        device->inputs = status.inputs;
        device->inputCount = std::uint8_t(8 * status.bytes);
    }
    emit inputsChanged(status.encoder, status.inputs, status.inputs ^ before);
}

void OrcSession::decoderAck(const orc::DecoderSwitch& ack) {
    const auto pending = switches_.find(ack.target);
    if (!ack.answer || pending == switches_.end() || pending->second.first != ack.position)
        return;
    switches_.erase(pending);
    emit switchReported(ack.target, ack.position, SwitchResult::Confirmed);
}

void OrcSession::overload(const orc::Overload& report) {
    const std::uint8_t port = report.hasPort ? report.port : WholeDevice;
    if (OrcDevice* device = registry_.byBusId(report.from.busId)) {
        if (report.kind == 0)
            device->overloads.erase(port);
        else
            device->overloads[port] = report.kind;
    }
    emit overloadChanged(report.from.busId, port, report.kind);
}

// Every ping period: a device that did not answer its last ping misses one; after missedPingsOffline it is
// offline. Every known device is pinged again (an offline one too, so that it comes back when it answers).
void OrcSession::tick() {
    for (const OrcDevice& known : registry_.devices()) {
        OrcDevice& device = *registry_.byUid(known.uid);
        if (device.state == OrcDevice::State::Assigning || device.state == OrcDevice::State::Unassigned)
            continue;
        if (device.pingOutstanding && ++device.missedPings >= settings_.timing.missedPingsOffline &&
            device.state == OrcDevice::State::Online) {
            device.state = OrcDevice::State::Offline;
            emit deviceChanged(device.uid);
        }
        device.pingOutstanding = true;
        send(orc::Ping{me(), device.uid});
    }
}

void OrcSession::assignTimedOut(std::uint32_t uid) {
    OrcDevice* device = registry_.byUid(uid);
    if (!device)
        return;
    if (++assignTries_[uid] < settings_.timing.assignTries) {
        send(orc::AssignBusId{me(), false, uid, device->busId});
        assignTimers_[uid].reset(startTimer([this, uid] { assignTimedOut(uid); }));
        return;
    }
    assignTimers_.erase(uid);
    device->state = OrcDevice::State::Unassigned;
    emit deviceChanged(uid);
}

void OrcSession::queryTimedOut(std::uint16_t encoder) {
    if (++queryTries_[encoder] <= settings_.timing.queryRetries) {
        send(orc::EncoderQuery{me(), false, encoder});
        queryTimers_[encoder].reset(startTimer([this, encoder] { queryTimedOut(encoder); }));
        return;
    }
    queryTimers_.erase(encoder);
    queryTries_.erase(encoder);
    emit queryFailed(encoder);
}

void OrcSession::switchTimedOut(std::uint16_t target) {
    const auto pending = switches_.find(target);
    if (pending == switches_.end())
        return;
    const std::uint8_t position = pending->second.first;
    switches_.erase(pending);
    emit switchReported(target, position, SwitchResult::SentUnconfirmed);
}

void OrcSession::send(const orc::Message& message) {
    bus_.transport().send(orc::encode(message));
}

orc::Origin OrcSession::me() const {
    return {0, std::uint8_t(orc::DeviceType::System), settings_.busId};
}

// A single-shot timer of the answer timeout; deleting it (erasing it from its map) cancels it.
QTimer* OrcSession::startTimer(std::function<void()> expired) {
    auto* timer = new QTimer;
    timer->setSingleShot(true);
    timer->setInterval(settings_.timing.answerTimeout);
    connect(timer, &QTimer::timeout, this, std::move(expired));
    timer->start();
    return timer;
}

} // namespace stellwerk::orccentral
