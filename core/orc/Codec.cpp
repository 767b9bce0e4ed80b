#include "orc/Codec.h"

#include "orc/CodecDetail.h"

#include <algorithm>
#include <type_traits>
#include <utility>

namespace stellwerk::orc {

std::string_view nameOf(const Message& message) {
    return std::visit([](const auto& m) { return std::decay_t<decltype(m)>::name; }, message);
}

namespace {
template <std::size_t... I>
std::vector<std::string_view> allNames(std::index_sequence<I...>) {
    return {std::variant_alternative_t<I, Message>::name...};
}

Message decodeGroup(const can::CanFrame& frame) {
    switch (readId(frame.id).group) {
    case group::System:
        return detail::decodeSystem(frame);
    case group::Loco:
        return detail::decodeLoco(frame);
    case group::Decoder:
        return detail::decodeDecoder(frame);
    case group::Encoder:
        return detail::decodeEncoder(frame);
    case group::Management:
        return detail::decodeManagement(frame);
    case group::Flash:
        return detail::decodeFlash(frame);
    default:
        break;
    }
    return detail::unknown(frame, "a command group the document does not define");
}
} // namespace

std::vector<std::string_view> messageNames() {
    return allNames(std::make_index_sequence<std::variant_size_v<Message>>());
}

bool isExtension(const Message& message) {
    return std::holds_alternative<FindAnswer>(message) || std::holds_alternative<AssignBusId>(message);
}

bool isOrc(const can::CanFrame& frame) {
    return frame.extended && isOrcId(frame.id);
}

Message decode(const can::CanFrame& frame) {
    if (!frame.extended)
        return detail::unknown(frame, "an 11-bit frame: OpenRailCAN uses 29-bit identifiers");
    if (!frame.isWellFormed())
        return detail::unknown(frame, "DLC above 8 or identifier above 29 bits");
    const Header h = readId(frame.id);
    if (h.prio == 0)
        return detail::unknown(frame, "priority 00 is never sent (kept for Maerklin/ESU)");
    if (h.group < 0x80)
        return detail::unknown(frame, "command group below 0x80 is not OpenRailCAN");
    if (frame.size() == 0)
        return detail::unknown(frame, "no sub-command: DB1 is missing");
    return decodeGroup(frame);
}

can::CanFrame encode(const Message& message) {
    return std::visit([](const auto& m) { return detail::encodeOne(m); }, message);
}

std::uint8_t defaultPriority(const Message& message) {
    Message copy = message;
    std::visit(
        [](auto& m) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(m)>, Unknown>)
                m.from.prio = 0;
        },
        copy);
    return readId(encode(copy).id).prio;
}

Header headerOf(const Message& message) {
    return readId(encode(message).id);
}

namespace detail {

Origin originOf(const can::CanFrame& frame) {
    const Header h = readId(frame.id);
    return {h.prio, h.type, h.busId};
}

Unknown unknown(const can::CanFrame& frame, std::string_view why) {
    Unknown result{frame.id, frame.extended, {std::uint8_t(frame.size()), {}}, why};
    std::copy_n(frame.data.begin(), frame.size(), result.payload.data.begin());
    return result;
}

std::optional<Target> targetOf(const Data& d) {
    switch (d.size()) {
    case 1:
        return Target::all();
    case 3:
        return Target::busId(d.u16(1));
    case 5:
        return Target::uid(d.u32(1));
    default:
        break;
    }
    return std::nullopt;
}

Payload& putTarget(Payload& payload, const Target& target) {
    switch (target.kind) {
    case Target::Kind::BusId:
        return payload.u16(std::uint16_t(target.value));
    case Target::Kind::Uid:
        return payload.u32(target.value);
    case Target::Kind::All:
        break;
    }
    return payload;
}

can::CanFrame frameOf(const Origin& from, std::uint8_t group, bool answer, std::uint8_t fallbackPrio,
                      const Payload& payload) {
    const std::uint8_t prio = from.prio != 0 ? from.prio : fallbackPrio;
    return payload.frame(makeId({prio, from.type, group, answer, from.busId}));
}

can::CanFrame encodeOne(const Unknown& m) {
    const auto bytes = std::span<const std::uint8_t>(m.payload.data.data(), m.payload.size);
    return m.extended ? can::CanFrame::extendedFrame(m.id, bytes) : can::CanFrame::standard(m.id, bytes);
}

} // namespace detail
} // namespace stellwerk::orc
