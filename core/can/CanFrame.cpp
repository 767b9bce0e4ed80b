#include "can/CanFrame.h"

#include <algorithm>

namespace stellwerk::can {

namespace {

CanFrame makeFrame(std::uint32_t id, bool extended, std::span<const std::uint8_t> payload) {
    CanFrame frame;
    frame.id = id;
    frame.extended = extended;
    frame.dlc = std::uint8_t(std::min<std::size_t>(payload.size(), 8));
    std::copy_n(payload.begin(), frame.dlc, frame.data.begin());
    return frame;
}

} // namespace

CanFrame CanFrame::standard(std::uint32_t id, std::span<const std::uint8_t> payload) {
    return makeFrame(id, false, payload);
}

CanFrame CanFrame::extendedFrame(std::uint32_t id, std::span<const std::uint8_t> payload) {
    return makeFrame(id, true, payload);
}

std::array<std::uint8_t, CanFrame::NetworkSize> CanFrame::toNetwork() const {
    std::array<std::uint8_t, NetworkSize> out{};
    out[0] = std::uint8_t(id >> 24);
    out[1] = std::uint8_t(id >> 16);
    out[2] = std::uint8_t(id >> 8);
    out[3] = std::uint8_t(id);
    out[4] = dlc;
    for (std::size_t i = 0; i < size(); ++i)
        out[5 + i] = data[i];
    return out;
}

CanFrame CanFrame::fromNetwork(std::span<const std::uint8_t, NetworkSize> bytes) {
    CanFrame frame;
    frame.id = (std::uint32_t(bytes[0]) << 24) | (std::uint32_t(bytes[1]) << 16) |
               (std::uint32_t(bytes[2]) << 8) | bytes[3];
    frame.dlc = bytes[4];
    for (std::size_t i = 0; i < 8; ++i)
        frame.data[i] = i < frame.size() ? bytes[5 + i] : 0;
    return frame;
}

} // namespace stellwerk::can
