#include "sim/MfxRegistry.h"

namespace stellwerk::sim {
namespace {

constexpr std::uint8_t MainTrackRange = 64;

bool isMfxRange(std::uint8_t range) {
    return range <= 32 || (range >= MainTrackRange && range <= MainTrackRange + 32);
}

} // namespace

MfxRegistry::MfxRegistry(const StationLayout& layout, const StationState& state,
                         const std::vector<std::uint32_t>& newDecoders)
    : state_(state) {
    for (const cs2config::Locomotive& loco : layout.locomotives().locomotives)
        if (loco.decoder == cs2config::LocomotiveDecoder::Mfx && loco.mfxUid != 0 &&
            loco.mfxUid != 0xFFFFFFFF)
            decoders_[loco.mfxUid] = std::uint16_t(loco.sid);
    for (const std::uint32_t uid : newDecoders)
        decoders_.try_emplace(uid, std::uint16_t(0));
}

bool MfxRegistry::handle(const cs2::Message& m, Outbox& out) {
    if (const auto* discovery = std::get_if<cs2::LocoDiscovery>(&m.body)) {
        if (discovery->uid)
            probe(*discovery, m, out);
        else
            discover(*discovery, m, out);
        return true;
    }
    if (const auto* request = std::get_if<cs2::MfxBind>(&m.body))
        return bind(*request, m, out), true;
    if (const auto* request = std::get_if<cs2::MfxVerify>(&m.body))
        return verify(*request, m, out), true;
    return false;
}

// Forms 1 and 2 (DLC 0/1): a whole cycle; one decoder per run. The steps are reported in form 3 (DLC 5:
// the UID bits found so far and the range, "zur Anzeige der MFX Erkennung"); the last step (range 32)
// is sent with and without the ASK ratio; no decoder found: DLC 0.
void MfxRegistry::discover(const cs2::LocoDiscovery& request, const cs2::Message& m, Outbox& out) {
    const bool mfxAsked = !request.range || *request.range == FullRange || *request.range == 0;
    const auto found = mfxAsked && mfxEnabled() ? firstUnbound() : std::nullopt;
    if (!found) {
        out.respond(cs2::LocoDiscovery{}, m.prio);
        return;
    }
    for (std::uint8_t range = 1; range < FullRange; ++range) {
        const std::uint32_t known = *found & (~std::uint32_t(0) << (32 - range));
        out.respond(cs2::LocoDiscovery{known, range, std::nullopt}, m.prio);
    }
    out.respond(cs2::LocoDiscovery{*found, FullRange, AskRatio}, m.prio);
    out.respond(cs2::LocoDiscovery{*found, FullRange, std::nullopt}, m.prio);
}

// Form 3 (DLC 5): one step of an mfx search: answered with the response bit when a decoder whose
// UID starts with the `range` leading bits of the given UID is unbound on the track.
void MfxRegistry::probe(const cs2::LocoDiscovery& request, const cs2::Message& m, Outbox& out) {
    const std::uint8_t range = request.range.value_or(0) % MainTrackRange;
    if (!isMfxRange(request.range.value_or(0)) || !mfxEnabled())
        return;
    const std::uint32_t mask = range == 0 ? 0 : ~std::uint32_t(0) << (32 - range);
    for (const auto& [uid, sid] : decoders_)
        if (sid == 0 && (uid & mask) == (*request.uid & mask)) {
            out.respond(cs2::LocoDiscovery{*request.uid, request.range, AskRatio}, m.prio);
            return;
        }
}

void MfxRegistry::bind(const cs2::MfxBind& request, const cs2::Message& m, Outbox& out) {
    // The station sends the bind to the track and confirms it; only a decoder that is there takes it.
    if (auto decoder = decoders_.find(request.mfxUid); decoder != decoders_.end()) {
        for (auto& [uid, sid] : decoders_)
            if (sid == request.sid)
                sid = 0; // a SID belongs to one decoder
        decoder->second = request.sid;
    }
    out.respond(m.body, m.prio);
}

void MfxRegistry::verify(const cs2::MfxVerify& request, const cs2::Message& m, Outbox& out) {
    if (sidOf(request.mfxUid) == request.sid && request.sid != 0) {
        out.respond(cs2::MfxVerify{request.mfxUid, request.sid, AskRatio}, m.prio);
        return;
    }
    out.respond(cs2::MfxVerify{request.mfxUid, 0, std::nullopt}, m.prio); // 3.3: negative, SID 0
}

std::optional<std::uint16_t> MfxRegistry::sidOf(std::uint32_t mfxUid) const {
    const auto decoder = decoders_.find(mfxUid);
    if (decoder == decoders_.end() || decoder->second == 0)
        return std::nullopt;
    return decoder->second;
}

bool MfxRegistry::sidBound(std::uint16_t sid) const {
    for (const auto& [uid, bound] : decoders_)
        if (bound == sid && sid != 0)
            return true;
    return false;
}

std::optional<std::uint32_t> MfxRegistry::firstUnbound() const {
    for (const auto& [uid, sid] : decoders_)
        if (sid == 0)
            return uid;
    return std::nullopt;
}

} // namespace stellwerk::sim
