#include "sim/SimulatedOrcDevices.h"

#include "orc/Codec.h"
#include "orc/Uid.h"

namespace stellwerk::sim {

SimulatedOrcDevice::SimulatedOrcDevice(std::uint32_t uid, orc::DeviceType type, QObject* parent)
    : QObject(parent), uid_(uid), type_(type), busId_(orc::wantedBusId(uid)) {}

void SimulatedOrcDevice::receive(const can::CanFrame& frame) {
    if (!plugged_ || !orc::isOrc(frame))
        return;
    const orc::Message message = orc::decode(frame);
    if (std::holds_alternative<orc::Unknown>(message))
        return;
    receiving_ = true;
    if (!manage(message))
        act(message);
    receiving_ = false;
    flush();
}

void SimulatedOrcDevice::plugIn() {
    plugged_ = true;
    busId_ = orc::wantedBusId(uid_);
    say(orc::PingAnswer{origin(), uid_, version()}); // "kann auch 'ungefragt' auftauchen"
}

void SimulatedOrcDevice::unplug() {
    plugged_ = false;
    outbox_.clear();
}

// Ping, Find and Stellwerk's bus-id assignment, which every device answers.
bool SimulatedOrcDevice::manage(const orc::Message& message) {
    if (const auto* ping = std::get_if<orc::Ping>(&message)) {
        if (ping->uid == uid_)
            say(orc::PingAnswer{origin(), uid_, version()});
        return true;
    }
    if (const auto* find = std::get_if<orc::Find>(&message)) {
        if (find->uid == 0 || find->uid == uid_)
            say(orc::FindAnswer{origin(), uid_, version()});
        return true;
    }
    if (const auto* assign = std::get_if<orc::AssignBusId>(&message)) {
        if (!assign->answer && assign->uid == uid_) {
            busId_ = assign->busId;
            say(orc::AssignBusId{origin(), true, uid_, busId_}); // from the new bus id
        }
        return true;
    }
    return false;
}

void SimulatedOrcDevice::say(const orc::Message& message) {
    if (!plugged_)
        return;
    outbox_.push_back(orc::encode(message));
    if (!receiving_)
        flush();
}

void SimulatedOrcDevice::flush() {
    if (outbox_.empty())
        return;
    std::vector<can::CanFrame> frames;
    frames.swap(outbox_);
    emit framesEmitted(frames);
}

orc::Origin SimulatedOrcDevice::origin() const {
    return {0, std::uint8_t(std::uint8_t(type_) & 3), busId_};
}

bool SimulatedOrcDevice::addressed(const orc::Target& target) const {
    return target.kind == orc::Target::Kind::All ||
           (target.kind == orc::Target::Kind::BusId && target.value == busId_) ||
           (target.kind == orc::Target::Kind::Uid && target.value == uid_);
}

// ---- booster ---------------------------------------------------------------------------------------------

SimulatedOrcBooster::SimulatedOrcBooster(std::uint32_t uid, QObject* parent)
    : SimulatedOrcDevice(uid, orc::DeviceType::System, parent) {}

void SimulatedOrcBooster::injectOverload(std::uint8_t port, std::uint8_t kind) {
    say(orc::Overload{origin(), false, kind, true, port});
}

void SimulatedOrcBooster::clearOverload(std::uint8_t port) {
    say(orc::Overload{origin(), false, 0, true, port});
}

std::uint16_t SimulatedOrcBooster::speed(std::uint16_t loco) const {
    const auto found = speeds_.find(loco);
    return found == speeds_.end() ? 0 : found->second;
}

void SimulatedOrcBooster::act(const orc::Message& message) {
    if (const auto* off = std::get_if<orc::AllOff>(&message); off && addressed(off->target))
        powered_ = false;
    else if (const auto* on = std::get_if<orc::AllOn>(&message); on && addressed(on->target))
        powered_ = true;
    else if (const auto* stop = std::get_if<orc::LocoStop>(&message); stop && addressed(stop->target)) {
        stopped_ = true;
        for (auto& [loco, speed] : speeds_)
            speed = 0;
    } else if (const auto* set = std::get_if<orc::LocoSpeed>(&message); set && !set->answer) {
        speeds_[set->target] = set->speed;
        stopped_ = false;
    } else if (const auto* query = std::get_if<orc::LocoSpeedQuery>(&message))
        say(orc::LocoSpeed{origin(), true, query->target,
                           speed(query->target)}); // O24: the state holder answers
}

// ---- decoder ---------------------------------------------------------------------------------------------

SimulatedOrcDecoder::SimulatedOrcDecoder(std::uint32_t uid, bool acknowledges, QObject* parent)
    : SimulatedOrcDevice(uid, orc::DeviceType::CanDecoder, parent), acknowledges_(acknowledges) {}

void SimulatedOrcDecoder::act(const orc::Message& message) {
    if (const auto* all = std::get_if<orc::AllDecoders>(&message)) {
        enabled_ = all->action != orc::GroupAction::Off;
        return;
    }
    const auto* command = std::get_if<orc::DecoderSwitch>(&message);
    if (!command || command->answer || command->target != busId() || !enabled_)
        return;
    outputs_ = command->position;
    ++switches_;
    if (acknowledges_)
        say(orc::DecoderSwitch{origin(), true, busId(), outputs_});
    emit switched(outputs_);
}

// ---- encoder ---------------------------------------------------------------------------------------------

SimulatedOrcEncoder::SimulatedOrcEncoder(std::uint32_t uid, QObject* parent)
    : SimulatedOrcDevice(uid, orc::DeviceType::CanEncoder, parent) {}

void SimulatedOrcEncoder::setInput(int input, bool on) {
    const std::uint32_t before = inputs_;
    const std::uint32_t bit = std::uint32_t(1) << (input & 31);
    inputs_ = on ? inputs_ | bit : inputs_ & ~bit;
    if (inputs_ != before)
        say(status(false)); // an event: D=0, as §Enkoder Status says
}

void SimulatedOrcEncoder::act(const orc::Message& message) {
    const auto* query = std::get_if<orc::EncoderQuery>(&message);
    if (query && (query->everyEncoder || query->target == busId()))
        say(status(true));
}

orc::EncoderStatus SimulatedOrcEncoder::status(bool answer) const {
    return {origin(), answer, busId(), 4, inputs_};
}

// ---- throttle --------------------------------------------------------------------------------------------

SimulatedOrcThrottle::SimulatedOrcThrottle(std::uint32_t uid, QObject* parent)
    : SimulatedOrcDevice(uid, orc::DeviceType::Loco, parent) {}

void SimulatedOrcThrottle::drive(std::uint16_t loco, std::uint16_t speed, bool forward) {
    say(orc::LocoSpeed{origin(), false, loco, std::uint16_t(speed | (forward ? 0 : 0x8000))});
}

void SimulatedOrcThrottle::setFunction(std::uint16_t loco, std::uint8_t function, bool on) {
    say(orc::LocoFunction{origin(), false, loco, function, std::uint8_t(on ? 1 : 0)});
}

void SimulatedOrcThrottle::setFunctions(std::uint16_t loco, std::uint32_t functions) {
    say(orc::LocoFunctions{origin(), false, loco, functions});
}

void SimulatedOrcThrottle::emergencyStop(std::optional<std::uint16_t> loco) {
    say(orc::LocoStop{origin(), loco ? orc::Target::busId(*loco) : orc::Target::all()});
}

void SimulatedOrcThrottle::querySpeed(std::uint16_t loco) {
    say(orc::LocoSpeedQuery{origin(), loco});
}

void SimulatedOrcThrottle::queryFunctions(std::uint16_t loco) {
    say(orc::LocoFunctionsQuery{origin(), loco});
}

std::optional<std::uint16_t> SimulatedOrcThrottle::answeredSpeed(std::uint16_t loco) const {
    const auto found = speeds_.find(loco);
    return found == speeds_.end() ? std::nullopt : std::optional(found->second);
}

std::optional<std::uint32_t> SimulatedOrcThrottle::answeredFunctions(std::uint16_t loco) const {
    const auto found = functions_.find(loco);
    return found == functions_.end() ? std::nullopt : std::optional(found->second);
}

void SimulatedOrcThrottle::act(const orc::Message& message) {
    if (const auto* speed = std::get_if<orc::LocoSpeed>(&message); speed && speed->answer)
        speeds_[speed->target] = speed->speed;
    else if (const auto* all = std::get_if<orc::LocoFunctions>(&message); all && all->answer)
        functions_[all->target] = all->functions;
}

} // namespace stellwerk::sim
