#pragma once

// Helpers shared by the simulated station's network tests: commands as a client sends them, the S88
// events a station emits, waiting on the event loop.

#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Header.h"
#include "cs2/Messages.h"
#include "sim/SimulatedStation.h"

#include <QObject>
#include <QTest>
#include <functional>
#include <ostream>
#include <utility>
#include <vector>

namespace stellwerk::cs2 {
// Failed comparisons show frames as the protocol document writes them.
inline void PrintTo(const CanFrame& frame, std::ostream* out) {
    *out << formatDocument(frame);
}
} // namespace stellwerk::cs2

namespace stellwerk::sim::test {

// Long enough for a loaded two-core machine; waits end as soon as the condition holds.
inline constexpr int WaitMs = 3000;
inline constexpr std::uint16_t ClientHash = 0x4711;

inline bool waitFor(const std::function<bool()>& condition, int timeoutMs = WaitMs) {
    return QTest::qWaitFor(condition, timeoutMs);
}

inline can::CanFrame command(cs2::MessageBody body) {
    return cs2::encode(cs2::Message{0, false, ClientHash, std::move(body)});
}

inline can::CanFrame speed(std::uint32_t locId, std::uint16_t value) {
    return command(cs2::LocoSpeed{cs2::LocId(locId), value});
}

inline can::CanFrame direction(std::uint32_t locId, cs2::Direction value) {
    return command(cs2::LocoDirection{cs2::LocId(locId), std::uint8_t(value)});
}

inline can::CanFrame switchAccessory(std::uint32_t locId, std::uint8_t position) {
    return command(cs2::AccessorySwitch{cs2::LocId(locId), position, 1, std::nullopt});
}

inline can::CanFrame ping() {
    return command(cs2::Ping{});
}

// One S88 event as a feedback module reports it: contact and its new state.
struct ContactEvent {
    std::uint16_t contact = 0;
    bool occupied = false;

    friend bool operator==(const ContactEvent&, const ContactEvent&) = default;
    friend std::ostream& operator<<(std::ostream& out, const ContactEvent& event) {
        return out << event.contact << (event.occupied ? "+" : "-");
    }
};

// Records the S88 events (0x11 with old and new state) a station emits.
class ContactRecorder {
public:
    explicit ContactRecorder(SimulatedStation& station) {
        QObject::connect(&station, &SimulatedStation::framesEmitted, &context_,
                         [this](const std::vector<can::CanFrame>& frames) {
                             for (const can::CanFrame& frame : frames)
                                 record(frame);
                         });
    }

    std::vector<ContactEvent> events;

private:
    void record(const can::CanFrame& frame) {
        const cs2::DecodeResult decoded = cs2::decode(frame);
        if (!decoded)
            return;
        if (const auto* event = std::get_if<cs2::S88Event>(&decoded->body); event && event->change)
            events.push_back({event->contact, event->change->newState != 0});
    }

    QObject context_;
};

} // namespace stellwerk::sim::test
