#pragma once

#include "can/CanFrame.h"

#include <QByteArray>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace stellwerk::transport {

// The 13-byte network form of CAN frames as CS2 gateways carry it in UDP datagrams and TCP streams.

// Frames in network form, one after the other (n x 13 bytes).
QByteArray encodeFrames(std::span<const can::CanFrame> frames);

// Reads one frame in network form and appends it to `out` when it is well formed (DLC at most 8).
// Returns false, appending nothing, for a malformed frame.
bool appendFrame(std::span<const std::uint8_t, can::CanFrame::NetworkSize> bytes,
                 std::vector<can::CanFrame>& out);

// What one UDP datagram held.
struct DatagramContent {
    bool wholeFrames = false;  // the size was a non-zero multiple of 13 bytes
    std::size_t frames = 0;    // well-formed frames appended to the output
    std::size_t malformed = 0; // frames left out (DLC above 8)
};

// Appends the frames of a datagram of n x 13 bytes to `out`. A datagram of any other size gives
// nothing (wholeFrames = false): the sender is broken or not a CS2 gateway.
DatagramContent decodeDatagram(std::span<const std::uint8_t> datagram, std::vector<can::CanFrame>& out);

// Views a byte array as unsigned bytes.
inline std::span<const std::uint8_t> asBytes(const QByteArray& bytes) {
    return {reinterpret_cast<const std::uint8_t*>(bytes.constData()), std::size_t(bytes.size())};
}

} // namespace stellwerk::transport
