#pragma once

#include "can/CanFrame.h"

#include <vector>

namespace stellwerk::bench {

// How many bit times a data frame takes on the wire: SOF, arbitration, control, data and CRC are stuffed
// (a bit of opposite value after five equal ones), then CRC delimiter, ACK, EOF and the 3-bit interframe
// space, 13 bits unstuffed. g = the stuffed header bits before the data: 34 for an 11-bit frame, 54 for a
// 29-bit one (Davis, Burns, Bril, Lukkien: "Controller Area Network (CAN) schedulability analysis").
inline unsigned headerBits(bool extended) {
    return extended ? 54 : 34;
}

// No stuff bit at all.
inline unsigned nominalBits(bool extended, unsigned dataBytes) {
    return headerBits(extended) + 8 * dataBytes + 13;
}

// The most stuff bits the stuffed part can need: one per four bits after the first.
inline unsigned worstCaseBits(bool extended, unsigned dataBytes) {
    const unsigned stuffed = headerBits(extended) + 8 * dataBytes;
    return stuffed + 13 + (stuffed - 1) / 4;
}

// The bits of one real frame, stuff bits counted exactly: the frame is laid out bit by bit and its CRC-15
// computed as a controller would.
inline unsigned exactBits(const can::CanFrame& frame) {
    std::vector<bool> bits{false}; // SOF
    const auto put = [&bits](std::uint32_t value, unsigned count) {
        for (unsigned i = count; i-- > 0;)
            bits.push_back((value >> i) & 1);
    };
    if (frame.extended) {
        put(frame.id >> 18, 11);
        put(1, 1); // SRR
        put(1, 1); // IDE
        put(frame.id & 0x3FFFF, 18);
        put(0, 3); // RTR, r1, r0
    } else {
        put(frame.id, 11);
        put(0, 3); // RTR, IDE, r0
    }
    put(frame.size(), 4);
    for (const std::uint8_t byte : frame.payload())
        put(byte, 8);
    std::uint32_t crc = 0;
    for (const bool bit : bits) {
        const bool top = ((crc >> 14) & 1) != bit;
        crc = (crc << 1) & 0x7FFF;
        if (top)
            crc ^= 0x4599;
    }
    put(crc, 15);
    unsigned stuff = 0, run = 0;
    bool last = !bits.front();
    for (const bool bit : bits) { // a stuff bit itself starts the next run
        run = bit == last ? run + 1 : 1;
        last = bit;
        if (run == 5) {
            ++stuff;
            last = !bit;
            run = 1;
        }
    }
    return unsigned(bits.size()) + stuff + 13;
}

} // namespace stellwerk::bench
