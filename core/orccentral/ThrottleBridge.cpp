#include "orccentral/ThrottleBridge.h"

#include "bus/Bus.h"
#include "orc/Codec.h"
#include "transport/Transport.h"

#include <algorithm>

namespace stellwerk::orccentral {

namespace {

constexpr std::uint16_t Reverse = 0x8000; // bit 15 of Lok Speed (Stellwerk's extension, notes O13)
constexpr int MaxSpeed = 1000;
constexpr int Functions = 32; // "Status für Fx0 bis Fx31"

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

} // namespace

std::optional<std::uint32_t> locIdOf(std::uint16_t zielId) {
    const bool mm = zielId >= 0x0001 && zielId <= 0x00FF;
    const bool mfx = zielId >= 0x4000 && zielId <= 0x7FFF;
    const bool dcc = zielId >= 0xC000;
    if (mm || mfx || dcc)
        return std::uint32_t(zielId);
    return std::nullopt;
}

ThrottleBridge::ThrottleBridge(bus::Bus& bus, ThrottleRailway& railway, std::uint16_t centralBusId,
                               QObject* parent)
    : QObject(parent), bus_(bus), railway_(railway), busId_(centralBusId) {
    bus_.subscribe(busreading::Protocol::Orc, this,
                   [this](const std::vector<can::CanFrame>& frames) { receive(frames); });
}

void ThrottleBridge::receive(const std::vector<can::CanFrame>& frames) {
    for (const can::CanFrame& frame : frames)
        handle(orc::decode(frame));
}

void ThrottleBridge::handle(const orc::Message& message) {
    std::visit(Overloaded{
                   [this](const orc::LocoSpeed& m) {
                       if (!m.answer)
                           speed(m);
                   },
                   [this](const orc::LocoFunctions& m) {
                       if (!m.answer)
                           functions(m);
                   },
                   [this](const orc::LocoFunction& m) {
                       if (!m.answer)
                           function(m);
                   },
                   [this](const orc::LocoStop& m) { stop(m); },
                   [this](const orc::LocoSpeedQuery& m) { answerSpeed(m.target); },
                   [this](const orc::LocoFunctionsQuery& m) { answerFunctions(m.target); },
                   [this](const orc::LocoFunctionQuery& m) { answerFunction(m.target, m.function); },
                   [this](const orc::LocoSpeedByUid& m) {
                       if (!m.answer)
                           ++refused_; // no CS2 locomotive is addressed by an ORC UID
                   },
                   [](const auto&) {},
               },
               message);
}

// Lok Speed, D=0: bit 15 is the direction. A change of direction goes first (the CS2 then stops the loco),
// and also when the station has not reported the direction, so that the loco runs the way the throttle says.
void ThrottleBridge::speed(const orc::LocoSpeed& command) {
    const auto locId = loco(command.target);
    if (!locId)
        return;
    const bool forward = (command.speed & Reverse) == 0;
    const std::optional<LocoState> now = railway_.loco(*locId);
    if (!now || now->forward != forward)
        railway_.setDirection(*locId, forward);
    railway_.setSpeed(*locId, std::min(command.speed & ~Reverse, MaxSpeed));
}

// Lok Funktion Schalten, all 32: the functions that differ from what the station reported (every one when it
// reported none).
void ThrottleBridge::functions(const orc::LocoFunctions& command) {
    const auto locId = loco(command.target);
    if (!locId)
        return;
    const std::optional<LocoState> now = railway_.loco(*locId);
    for (int n = 0; n < Functions; ++n) {
        const bool on = (command.functions >> n & 1) != 0;
        if (!now || ((now->functions >> n & 1) != 0) != on)
            railway_.setFunction(*locId, n, on);
    }
}

// Lok Funktion Schalten, one: Wert 0 is off, any other value on ("für 'normale' DCC und MM Lok Dekoder").
void ThrottleBridge::function(const orc::LocoFunction& command) {
    if (command.function >= Functions) {
        ++refused_;
        emit commandRefused(command.target, QStringLiteral("function %1 is above F31").arg(command.function));
        return;
    }
    if (const auto locId = loco(command.target))
        railway_.setFunction(*locId, command.function, command.value != 0);
}

// Lok(s) Nothalt: every loco (the station's STOP), or one by Ziel-Id. By UID the CS2 has no loco to stop.
void ThrottleBridge::stop(const orc::LocoStop& command) {
    if (command.target.kind == orc::Target::Kind::All)
        return railway_.stopAll();
    if (command.target.kind == orc::Target::Kind::Uid) {
        ++refused_;
        emit commandRefused(0, QStringLiteral("Lok Nothalt by UID: no CS2 locomotive is addressed so"));
        return;
    }
    if (const auto locId = loco(std::uint16_t(command.target.value)))
        railway_.emergencyStop(*locId);
}

void ThrottleBridge::answerSpeed(std::uint16_t zielId) {
    if (const auto now = state(zielId))
        send(orc::LocoSpeed{me(), true, zielId, std::uint16_t(now->speed | (now->forward ? 0 : Reverse))});
}

void ThrottleBridge::answerFunctions(std::uint16_t zielId) {
    if (const auto now = state(zielId))
        send(orc::LocoFunctions{me(), true, zielId, now->functions});
}

void ThrottleBridge::answerFunction(std::uint16_t zielId, std::uint8_t function) {
    if (function >= Functions)
        return;
    if (const auto now = state(zielId))
        send(orc::LocoFunction{me(), true, zielId, function, std::uint8_t(now->functions >> function & 1)});
}

// The Loc-ID of a command's Ziel-Id; a Ziel-Id that is no CS2 locomotive is refused and counted.
std::optional<std::uint32_t> ThrottleBridge::loco(std::uint16_t zielId) {
    const auto locId = locIdOf(zielId);
    if (!locId) {
        ++refused_;
        emit commandRefused(zielId, QStringLiteral("Ziel-Id 0x%1 is no MM, mfx or DCC locomotive")
                                        .arg(zielId, 4, 16, QLatin1Char('0')));
    }
    return locId;
}

// The state a query is answered from; none for an unknown range (refused) or an unreported loco.
std::optional<LocoState> ThrottleBridge::state(std::uint16_t zielId) {
    const auto locId = loco(zielId);
    if (!locId)
        return std::nullopt;
    const std::optional<LocoState> now = railway_.loco(*locId);
    if (!now)
        ++unanswered_;
    return now;
}

void ThrottleBridge::send(const orc::Message& message) {
    bus_.transport().send(orc::encode(message));
}

orc::Origin ThrottleBridge::me() const {
    return {0, std::uint8_t(orc::DeviceType::System), busId_};
}

} // namespace stellwerk::orccentral
