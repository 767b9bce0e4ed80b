#pragma once

#include "can/CanFrame.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace stellwerk::transport {

// Cuts a TCP byte stream into 13-byte frames whatever the segmentation: the bytes of a frame that is
// not complete yet wait for the next read.
class FrameAssembler {
public:
    // Appends the well-formed frames completed by `bytes` to `out`, in stream order. Frames that are
    // not well formed (DLC above 8) are left out; returns how many there were.
    std::size_t feed(std::span<const std::uint8_t> bytes, std::vector<can::CanFrame>& out);

    // Bytes of an incomplete frame waiting for the rest (0..12).
    std::size_t pendingBytes() const { return pendingSize_; }
    // Forgets an incomplete frame (the connection it came from is gone).
    void clear() { pendingSize_ = 0; }

private:
    std::size_t completePending(std::span<const std::uint8_t>& bytes, std::vector<can::CanFrame>& out);

    std::array<std::uint8_t, can::CanFrame::NetworkSize> pending_{};
    std::size_t pendingSize_ = 0;
};

} // namespace stellwerk::transport
