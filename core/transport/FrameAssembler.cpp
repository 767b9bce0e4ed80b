#include "transport/FrameAssembler.h"

#include "transport/NetworkFraming.h"

#include <algorithm>

namespace stellwerk::transport {

using can::CanFrame;

std::size_t FrameAssembler::feed(std::span<const std::uint8_t> bytes, std::vector<CanFrame>& out) {
    std::size_t malformed = completePending(bytes, out);
    while (bytes.size() >= CanFrame::NetworkSize) {
        if (!appendFrame(bytes.first<CanFrame::NetworkSize>(), out))
            ++malformed;
        bytes = bytes.subspan(CanFrame::NetworkSize);
    }
    std::copy(bytes.begin(), bytes.end(), pending_.begin() + std::ptrdiff_t(pendingSize_));
    pendingSize_ += bytes.size();
    return malformed;
}

// Fills up the waiting partial frame from the front of `bytes` (which is advanced past what was used).
std::size_t FrameAssembler::completePending(std::span<const std::uint8_t>& bytes,
                                            std::vector<CanFrame>& out) {
    if (pendingSize_ == 0)
        return 0;
    const std::size_t used = std::min(bytes.size(), CanFrame::NetworkSize - pendingSize_);
    std::copy_n(bytes.begin(), used, pending_.begin() + std::ptrdiff_t(pendingSize_));
    pendingSize_ += used;
    bytes = bytes.subspan(used);
    if (pendingSize_ < CanFrame::NetworkSize)
        return 0;
    pendingSize_ = 0;
    return appendFrame(pending_, out) ? 0 : 1;
}

} // namespace stellwerk::transport
