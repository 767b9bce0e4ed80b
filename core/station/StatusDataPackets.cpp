#include "station/StatusDataPackets.h"

#include "cs2/Hash.h"

namespace stellwerk::station {

void StatusDataPackets::add(std::uint16_t hash, const cs2::RawBytes& packet) {
    packets_[cs2::packetNumberFromHash(hash)] = packet;
}

std::vector<std::uint8_t> StatusDataPackets::assemble() const {
    std::vector<std::uint8_t> bytes;
    bytes.reserve(packets_.size() * 8);
    for (const auto& [number, packet] : packets_)
        bytes.insert(bytes.end(), packet.view().begin(), packet.view().end());
    return bytes;
}

} // namespace stellwerk::station
