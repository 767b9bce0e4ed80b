#pragma once

#include "sim/StationLayout.h"
#include "sim/StationState.h"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::sim {

// The mfx decoders on the simulated track (the layout's mfx locomotives) and which session id
// each is bound to: answers discovery (3.1), bind (3.2) and verify (3.3). Locomotives with a
// `.sid` in lokomotive.cs2 start bound, as on a station that registered them before; the others, and
// the decoders `newDecoders` puts on the track (locomotives no station has seen yet), wait to be
// discovered.
class MfxRegistry {
public:
    static constexpr std::uint8_t AskRatio = 0xD1; // the document's example value
    static constexpr std::uint8_t FullRange = 32;

    MfxRegistry(const StationLayout& layout, const StationState& state,
                const std::vector<std::uint32_t>& newDecoders = {});

    bool handle(const cs2::Message& message, Outbox& out);

    // The SID a decoder is bound to, or nullopt.
    std::optional<std::uint16_t> sidOf(std::uint32_t mfxUid) const;
    // True when some decoder answers under this SID (an mfx Loc-ID is 0x4000 + SID).
    bool sidBound(std::uint16_t sid) const;

private:
    void discover(const cs2::LocoDiscovery& request, const cs2::Message& message, Outbox& out);
    void probe(const cs2::LocoDiscovery& request, const cs2::Message& message, Outbox& out);
    void bind(const cs2::MfxBind& request, const cs2::Message& message, Outbox& out);
    void verify(const cs2::MfxVerify& request, const cs2::Message& message, Outbox& out);
    std::optional<std::uint32_t> firstUnbound() const;
    bool mfxEnabled() const { return state_.trackProtocols & 0x02; }

    const StationState& state_;
    std::map<std::uint32_t, std::uint16_t> decoders_; // mfx UID -> bound SID (0 = not bound)
};

} // namespace stellwerk::sim
