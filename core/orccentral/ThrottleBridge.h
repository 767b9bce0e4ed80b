#pragma once

#include "can/CanFrame.h"
#include "orc/Messages.h"

#include <QObject>
#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::bus {
class Bus;
}

namespace stellwerk::orccentral {

// How a locomotive runs, as the railway's station confirmed it.
struct LocoState {
    int speed = 0; // 0..1000
    bool forward = true;
    std::uint32_t functions = 0; // bit n: function n is on
};

// The railway as OpenRailCAN throttles drive it, free of any protocol: the app implements it on its railway
// model (the intents become the same CS2 commands its own throttles send), so that a throttle's command
// given up on is never sent later and none waits for a station that is gone.
class ThrottleRailway {
public:
    virtual ~ThrottleRailway() = default;

    // nullopt while the station has not reported the locomotive's speed and direction.
    virtual std::optional<LocoState> loco(std::uint32_t locId) const = 0;
    virtual void setSpeed(std::uint32_t locId, int speed) = 0;
    virtual void setDirection(std::uint32_t locId, bool forward) = 0;
    virtual void setFunction(std::uint32_t locId, int function, bool on) = 0;
    virtual void emergencyStop(std::uint32_t locId) = 0;
    // Lok(s) Nothalt to every locomotive: the station's STOP.
    virtual void stopAll() = 0;
};

// The CS2 Loc-ID of an ORC loco Ziel-Id (notes A3.1, the CS2 Loc-ID schema, marked assumed there): MM locos
// 0x0001-0x00FF, mfx 0x4000-0x7FFF and DCC 0xC000-0xFFFF are the same numbers on both sides. Anything else
// (MM loco 0, accessories, SX1, the unused ranges) is no locomotive the CS2 drives: nullopt.
std::optional<std::uint32_t> locIdOf(std::uint16_t zielId);

// Forwards loco control (group 0x81) from OpenRailCAN throttles on a bus to the CS2 station (issue 15):
// Lok Speed and Lok Funktion with D=0 and Lok(s) Nothalt become the railway's loco intents, and the speed
// and function queries are answered from the railway's loco state by the central (notes O24: the state
// holder answers). Answers of boosters (D=1) are theirs and left alone. It subscribes to its bus's ORC
// frames beside the OrcSession and sends from the central's bus id.
class ThrottleBridge final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ThrottleBridge)

public:
    ThrottleBridge(bus::Bus& bus, ThrottleRailway& railway, std::uint16_t centralBusId,
                   QObject* parent = nullptr);

    // Commands for a Ziel-Id that is no CS2 locomotive (or by UID), refused.
    std::uint64_t refused() const { return refused_; }
    // Queries for a locomotive whose state the station has not reported, left unanswered.
    std::uint64_t unanswered() const { return unanswered_; }

signals:
    // A command that was refused, for the log: what came, and why.
    void commandRefused(std::uint16_t zielId, const QString& why);

private:
    void receive(const std::vector<can::CanFrame>& frames);
    void handle(const orc::Message& message);
    void speed(const orc::LocoSpeed& command);
    void functions(const orc::LocoFunctions& command);
    void function(const orc::LocoFunction& command);
    void stop(const orc::LocoStop& command);
    void answerSpeed(std::uint16_t zielId);
    void answerFunctions(std::uint16_t zielId);
    void answerFunction(std::uint16_t zielId, std::uint8_t function);
    std::optional<std::uint32_t> loco(std::uint16_t zielId);
    std::optional<LocoState> state(std::uint16_t zielId);
    void send(const orc::Message& message);
    orc::Origin me() const;

    bus::Bus& bus_;
    ThrottleRailway& railway_;
    std::uint16_t busId_;
    std::uint64_t refused_ = 0;
    std::uint64_t unanswered_ = 0;
};

} // namespace stellwerk::orccentral
