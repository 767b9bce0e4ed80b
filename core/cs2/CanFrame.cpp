#include "cs2/CanFrame.h"

namespace stellwerk::cs2 {

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

} // namespace stellwerk::cs2
