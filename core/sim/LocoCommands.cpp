#include "sim/LocoCommands.h"

#include <algorithm>

namespace stellwerk::sim {
namespace {

constexpr std::uint8_t Forward = 1, Backward = 2, Toggle = 3;
constexpr std::uint8_t FunctionCount = 32;
constexpr std::uint16_t MaxCv = 1024;
constexpr unsigned MaxMfxBytes = 63, Sx1Cvs = 5;

std::uint16_t packed(std::uint16_t number, std::uint8_t index) {
    return cs2::CvAddress{number, index}.packed();
}

// CV1 = address, CV2..5 = start voltage, acceleration, braking, top speed (from lokomotive.cs2 where
// it has them), CV7/8 = version and manufacturer (131 = Märklin), CV29 = configuration (28 steps;
// long address above 127).
std::map<std::uint16_t, std::uint8_t> defaultCvs(cs2::LocId loco, const cs2config::Locomotive* known) {
    const std::uint32_t address = loco.offset();
    const bool longAddress = loco.protocol() == cs2::Protocol::Dcc && address > 127;
    auto fromFile = [known](int cs2config::Locomotive::*field, std::uint8_t fallback) {
        return known && known->*field > 0 ? std::uint8_t(std::clamp(known->*field, 1, 255)) : fallback;
    };
    std::map<std::uint16_t, std::uint8_t> cvs{
        {1, std::uint8_t(longAddress ? 3 : address)},
        {2, fromFile(&cs2config::Locomotive::vMin, 1)},
        {3, fromFile(&cs2config::Locomotive::acceleration, 10)},
        {4, fromFile(&cs2config::Locomotive::braking, 10)},
        {5, fromFile(&cs2config::Locomotive::vMax, 255)},
        {7, 0x23},
        {8, 131},
        {29, std::uint8_t(longAddress ? 0x26 : 0x06)},
    };
    if (longAddress) {
        cvs[17] = std::uint8_t(0xC0 | (address >> 8));
        cvs[18] = std::uint8_t(address);
    }
    return cvs;
}

} // namespace

bool LocoCommands::handle(const cs2::Message& m, Outbox& out) {
    if (const auto* command = std::get_if<cs2::LocoSpeed>(&m.body))
        return speed(*command, m, out), true;
    if (const auto* command = std::get_if<cs2::LocoDirection>(&m.body))
        return direction(*command, m, out), true;
    if (const auto* command = std::get_if<cs2::LocoFunction>(&m.body))
        return function(*command, m, out), true;
    return false;
}

void LocoCommands::speed(const cs2::LocoSpeed& command, const cs2::Message& m, Outbox& out) {
    if (!command.speed) { // query: the speed when the loco is known, else the request as it came
        const SimulatedLoco* loco = state_.findLoco(command.loco.value());
        out.respond(loco && loco->inCycle ? cs2::LocoSpeed{command.loco, loco->speed} : command, m.prio);
        return;
    }
    SimulatedLoco& loco = state_.loco(command.loco.value());
    loco.inCycle = true;
    loco.speed = *command.speed;
    out.respond(m.body, m.prio);
}

void LocoCommands::direction(const cs2::LocoDirection& command, const cs2::Message& m, Outbox& out) {
    if (!command.direction) { // query: answered in any case, "keep" (0) when the loco is unknown
        const SimulatedLoco* loco = state_.findLoco(command.loco.value());
        const std::uint8_t value = loco && loco->inCycle ? loco->direction : 0;
        out.respond(cs2::LocoDirection{command.loco, value}, m.prio);
        return;
    }
    SimulatedLoco& loco = state_.loco(command.loco.value());
    loco.inCycle = true;
    std::uint8_t next = loco.direction;
    if (*command.direction == Forward || *command.direction == Backward)
        next = *command.direction;
    else if (*command.direction == Toggle)
        next = loco.direction == Forward ? Backward : Forward;
    if (next != loco.direction)
        loco.speed = 0; // 3.5: a change of direction brings the loco to speed 0
    loco.direction = next;
    out.respond(m.body, m.prio);
}

void LocoCommands::function(const cs2::LocoFunction& command, const cs2::Message& m, Outbox& out) {
    if (command.function >= FunctionCount)
        return;           // only F0..F31 exist
    if (!command.value) { // query: active (1) or not, from the station's own memory
        const SimulatedLoco* loco = state_.findLoco(command.loco.value());
        const std::uint8_t value = loco && loco->inCycle ? loco->functions[command.function] : 0;
        out.respond(cs2::LocoFunction{command.loco, command.function, value, std::nullopt}, m.prio);
        return;
    }
    SimulatedLoco& loco = state_.loco(command.loco.value());
    loco.inCycle = true;
    loco.functions[command.function] = *command.value ? 1 : 0; // the status, not the dim value
    out.respond(m.body, m.prio);
}

bool DecoderProgramming::handle(const cs2::Message& m, Outbox& out) {
    if (const auto* request = std::get_if<cs2::ConfigRead>(&m.body))
        return read(*request, m, out), true;
    if (const auto* request = std::get_if<cs2::ConfigWrite>(&m.body))
        return write(*request, m, out), true;
    return false;
}

bool DecoderProgramming::decoderPresent(cs2::LocId loco) const {
    switch (loco.protocol()) {
    case cs2::Protocol::Dcc:
    case cs2::Protocol::Sx1:
    case cs2::Protocol::Mm2:
        return true;
    case cs2::Protocol::Mfx:
        return mfx_.sidBound(std::uint16_t(loco.offset()));
    default:
        return false;
    }
}

std::map<std::uint16_t, std::uint8_t>& DecoderProgramming::cvs(cs2::LocId loco) {
    SimulatedLoco& decoder = state_.loco(loco.value());
    if (decoder.cvs.empty())
        decoder.cvs = defaultCvs(loco, layout_.locomotives().find(loco.value()));
    return decoder.cvs;
}

void DecoderProgramming::read(const cs2::ConfigRead& request, const cs2::Message& m, Outbox& out) {
    const cs2::Protocol protocol = request.loco.protocol();
    const bool mfx = protocol == cs2::Protocol::Mfx;
    unsigned count = request.count.value_or(1) == 0 ? 256u : request.count.value_or(1);
    count = mfx ? std::min(count, MaxMfxBytes) : count;
    const std::uint16_t last = protocol == cs2::Protocol::Sx1 ? Sx1Cvs : MaxCv;
    if (protocol == cs2::Protocol::Mm2 || !decoderPresent(request.loco) || request.cv.number == 0 ||
        request.cv.number > last) {
        out.respond(cs2::ConfigRead{request.loco, request.cv, std::nullopt, std::nullopt}, m.prio);
        return; // 3.7: nothing could be read: DLC 6 without a value
    }
    auto& store = cvs(request.loco);
    for (unsigned i = 0; i < count; ++i) {
        cs2::CvAddress at = request.cv;
        if (mfx)
            at.index = std::uint8_t(request.cv.index + i);
        else if ((at.number = std::uint16_t(request.cv.number + i)) > last)
            break;
        const auto value = store.find(packed(at.number, at.index));
        out.respond(cs2::ConfigRead{request.loco, at, std::nullopt, value == store.end() ? 0 : value->second},
                    m.prio);
    }
}

void DecoderProgramming::write(const cs2::ConfigWrite& request, const cs2::Message& m, Outbox& out) {
    const cs2::Protocol protocol = request.loco.protocol();
    const std::uint16_t last = protocol == cs2::Protocol::Sx1 ? Sx1Cvs : MaxCv;
    std::uint8_t result = 0;
    if (decoderPresent(request.loco) && request.cv.number >= 1 && request.cv.number <= last) {
        cvs(request.loco)[packed(request.cv.number, request.cv.index)] = request.value;
        // MM2 decoders cannot be read back: the write is confirmed but not verified.
        result = protocol == cs2::Protocol::Mm2 ? cs2::ConfigWrite::WriteOk
                                                : cs2::ConfigWrite::WriteOk | cs2::ConfigWrite::VerifyOk;
    }
    out.respond(cs2::ConfigWrite{request.loco, request.cv, request.value, result}, m.prio);
}

} // namespace stellwerk::sim
