#pragma once

#include "cs2/Messages.h"

#include <cstdint>
#include <map>
#include <vector>

namespace stellwerk::station {

// The data packets of one status-data index (document 6.2: hash 0x0301, 0x0302, ...), kept by packet
// number so that they join in order whatever order they arrived in; a repeated number replaces the one
// before.
class StatusDataPackets {
public:
    void add(std::uint16_t hash, const cs2::RawBytes& packet);
    void clear() { packets_.clear(); }
    bool empty() const { return packets_.empty(); }
    // The bytes of every packet, in packet-number order.
    std::vector<std::uint8_t> assemble() const;

private:
    std::map<std::uint16_t, cs2::RawBytes> packets_;
};

} // namespace stellwerk::station
