#include "mcan/Codec.h"

#include "mcan/CodecDetail.h"

#include <type_traits>
#include <utility>

namespace stellwerk::mcan {

std::string_view roleName(HandleRole role) {
    switch (role) {
    case HandleRole::Start:
        return "start";
    case HandleRole::Poll:
        return "poll";
    case HandleRole::SlaveDescription:
        return "slave-description";
    case HandleRole::SystemStatus:
        return "system-status";
    case HandleRole::Loco:
        return "loco";
    case HandleRole::Unknown:
        break;
    }
    return "unknown";
}

std::string_view nameOf(const Message& message) {
    return std::visit([](const auto& m) { return std::decay_t<decltype(m)>::name; }, message);
}

namespace {
template <std::size_t... I>
std::vector<std::string_view> allNames(std::index_sequence<I...>) {
    return {std::variant_alternative_t<I, Message>::name...};
}
} // namespace

std::vector<std::string_view> messageNames() {
    return allNames(std::make_index_sequence<std::variant_size_v<Message>>());
}

bool isMcan(const can::CanFrame& frame) {
    return frame.extended && isMcanId(frame.id);
}

bool fromMaster(const can::CanFrame& frame) {
    return !isSlaveNode(std::uint8_t(frame.id & 0x7F));
}

Message decode(const can::CanFrame& frame, HandleRole role) {
    if (!frame.extended)
        return detail::unknown(frame, "an 11-bit frame: M-CAN uses 29-bit identifiers");
    if (!frame.isWellFormed())
        return detail::unknown(frame, "DLC above 8 or identifier above 29 bits");
    switch (layoutOf(frame.id)) {
    case Layout::Login:
        return detail::decodeLogin(frame);
    case Layout::Flash:
        return detail::decodeFlash(frame);
    case Layout::Session:
        break;
    }
    return detail::decodeSession(frame, role);
}

can::CanFrame encode(const Message& message) {
    return std::visit([](const auto& m) { return detail::encodeOne(m); }, message);
}

} // namespace stellwerk::mcan
