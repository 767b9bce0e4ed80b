#pragma once

#include "sim/MfxRegistry.h"
#include "sim/StationLayout.h"
#include "sim/StationState.h"

namespace stellwerk::sim {

// Chapter 3 driving commands: speed, direction (a change stops the loco), functions F0-F31. The
// first driving command takes a loco into the refresh cycle; queries of a loco outside it get the
// document's "unknown" answers.
class LocoCommands {
public:
    explicit LocoCommands(StationState& state) : state_(state) {}

    bool handle(const cs2::Message& message, Outbox& out);

private:
    void speed(const cs2::LocoSpeed& command, const cs2::Message& message, Outbox& out);
    void direction(const cs2::LocoDirection& command, const cs2::Message& message, Outbox& out);
    void function(const cs2::LocoFunction& command, const cs2::Message& message, Outbox& out);

    StationState& state_;
};

// Chapter 3.7/3.8: reads and writes the CVs of the simulated decoders. A decoder's store starts
// with plausible values (CV1 = address, limits from lokomotive.cs2). MM2 decoders cannot be read;
// an mfx SID nobody is bound to has no decoder to answer.
class DecoderProgramming {
public:
    DecoderProgramming(const StationLayout& layout, StationState& state, const MfxRegistry& mfx)
        : layout_(layout), state_(state), mfx_(mfx) {}

    bool handle(const cs2::Message& message, Outbox& out);

private:
    void read(const cs2::ConfigRead& request, const cs2::Message& message, Outbox& out);
    void write(const cs2::ConfigWrite& request, const cs2::Message& message, Outbox& out);
    bool decoderPresent(cs2::LocId loco) const;
    std::map<std::uint16_t, std::uint8_t>& cvs(cs2::LocId loco);

    const StationLayout& layout_;
    StationState& state_;
    const MfxRegistry& mfx_;
};

} // namespace stellwerk::sim
