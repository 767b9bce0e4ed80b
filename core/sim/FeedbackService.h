#pragma once

#include "sim/StationState.h"

namespace stellwerk::sim {

// Chapter 5: the S88 contacts of the layout as a Link S88 reports them: an event (0x11, DLC 8) on
// every change, answers to contact queries and to the old register polling (0x10). The station's
// own S88 bus is feedback device 0 for polling.
class FeedbackService {
public:
    static constexpr std::uint16_t MaxContactsPerQuery = 256;

    FeedbackService(StationState& state, const StationIdentity& identity)
        : state_(state), identity_(identity) {}

    bool handle(const cs2::Message& message, Outbox& out);
    // A contact changed: the event frame (nothing when the state did not change).
    void change(std::uint16_t device, std::uint16_t contact, bool occupied, Outbox& out);

private:
    void poll(const cs2::S88Poll& request, const cs2::Message& message, Outbox& out);
    void query(const cs2::S88Event& request, const cs2::Message& message, Outbox& out);
    cs2::S88Event answer(std::uint16_t device, std::uint16_t contact) const;
    bool occupied(std::uint16_t device, std::uint16_t contact) const;

    StationState& state_;
    const StationIdentity& identity_;
};

} // namespace stellwerk::sim
