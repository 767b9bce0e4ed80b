#include "sim/SystemCommands.h"

namespace stellwerk::sim {

bool SystemCommands::handle(const cs2::Message& m, Outbox& out) {
    if (const auto* stop = std::get_if<cs2::SystemStop>(&m.body))
        return power(stop->target, TrackPower::Stopped, m, out), true;
    if (const auto* go = std::get_if<cs2::SystemGo>(&m.body))
        return power(go->target, TrackPower::Running, m, out), true;
    if (const auto* halt = std::get_if<cs2::SystemHalt>(&m.body))
        return power(halt->target, TrackPower::Halted, m, out), true;
    if (const auto* emergency = std::get_if<cs2::LocoEmergencyStop>(&m.body))
        return emergencyStop(*emergency, m, out), true;
    if (const auto* cycle = std::get_if<cs2::LocoCycleEnd>(&m.body))
        return cycleEnd(*cycle, m, out), true;
    if (const auto* protocol = std::get_if<cs2::LocoProtocol>(&m.body))
        return locoProtocol(*protocol, m, out), true;
    return settings(m, out);
}

void SystemCommands::power(std::uint32_t target, TrackPower power, const cs2::Message& m, Outbox& out) {
    if (!identity_.addressedBy(target))
        return;
    state_.power = power;
    if (power == TrackPower::Halted) // 2.3: every loco brakes to speed 0, power stays on
        for (auto& [locId, loco] : state_.locos)
            loco.speed = 0;
    out.respond(m.body, m.prio);
}

void SystemCommands::emergencyStop(const cs2::LocoEmergencyStop& command, const cs2::Message& m,
                                   Outbox& out) {
    // 2.4: only a loco already in the cycle stops; the command does not take a new one in.
    if (auto it = state_.locos.find(command.loco.value()); it != state_.locos.end() && it->second.inCycle)
        it->second.speed = 0;
    out.respond(m.body, m.prio);
}

void SystemCommands::cycleEnd(const cs2::LocoCycleEnd& command, const cs2::Message& m, Outbox& out) {
    const std::uint32_t id = command.loco.value();
    const bool everyLoco = id == 0 || identity_.isOurDevice(id);
    if (id > 0xFFFF && !everyLoco)
        return; // another station's UID
    for (auto& [locId, loco] : state_.locos)
        if (everyLoco || locId == id) {
            loco.inCycle = false;
            loco.speed = 0;
        }
    out.respond(m.body, m.prio);
}

void SystemCommands::locoProtocol(const cs2::LocoProtocol& command, const cs2::Message& m, Outbox& out) {
    const cs2::Protocol protocol = command.loco.protocol();
    if (protocol != cs2::Protocol::Dcc && protocol != cs2::Protocol::Mm2)
        return; // 2.6: no answer for a Loc-ID that is neither DCC nor MM2
    SimulatedLoco& loco = state_.loco(command.loco.value());
    loco.trackProtocol = command.trackProtocol;
    loco.inCycle = true; // the first command takes the loco into the cycle
    out.respond(m.body, m.prio);
}

bool SystemCommands::settings(const cs2::Message& m, Outbox& out) {
    auto answer = [&](std::uint32_t target, auto apply) {
        if (identity_.addressedBy(target)) {
            apply();
            out.respond(m.body, m.prio);
        }
        return true;
    };
    if (const auto* time = std::get_if<cs2::AccessorySwitchTime>(&m.body))
        return answer(time->target, [&] {
            if (time->time10ms)
                state_.switchTime10ms = *time->time10ms;
        });
    if (std::get_if<cs2::MfxFastRead>(&m.body))
        return out.respond(m.body, m.prio), true; // 2.8: always confirmed
    if (const auto* protocols = std::get_if<cs2::TrackProtocols>(&m.body))
        return answer(protocols->target, [&] { state_.trackProtocols = protocols->mask; });
    if (const auto* counter = std::get_if<cs2::MfxRegistrationCounter>(&m.body))
        return answer(counter->target, [&] { state_.mfxRegistrationCounter = counter->counter; });
    if (const auto* reset = std::get_if<cs2::SystemReset>(&m.body))
        return answer(reset->target, [&] { this->reset(); });
    if (const auto* id = std::get_if<cs2::DeviceId>(&m.body)) {
        if (!identity_.isOurDevice(id->target))
            return true;
        cs2::DeviceId answer = *id;
        if (id->deviceId && *id->deviceId != 0 && *id->deviceId != 0xFFFF)
            state_.deviceId = *id->deviceId; // 2.13: 0 and 0xFFFF are not valid ids
        answer.deviceId = state_.deviceId;   // the query is answered in the DLC 7 form
        out.respond(answer, m.prio);
        return true;
    }
    return false;
}

void SystemCommands::reset() {
    state_.power = TrackPower::Stopped;
    state_.trackProtocols = 0x07;
    state_.switchTime10ms = 0;
    for (auto& [locId, loco] : state_.locos) {
        loco.inCycle = false;
        loco.speed = 0;
    }
}

} // namespace stellwerk::sim
