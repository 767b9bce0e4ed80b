#pragma once

#include "base/Expected.h"
#include "z21/Packet.h"
#include "z21/Replies.h"

#include <cstdint>
#include <span>
#include <vector>

namespace stellwerk::z21 {

// A reply or broadcast as the packet the server sends, X-bus ones with their XOR byte.
std::vector<std::uint8_t> encodeReply(const Reply& reply);

// The replies of one datagram (what a client reads; for tests and test clients), and the packets that
// are none, with why. Loco info is read with or without DB8.
struct DatagramReplies {
    std::vector<Reply> replies;
    std::vector<PacketError> errors;
};
DatagramReplies readReplies(std::span<const std::uint8_t> datagram);
Expected<Reply, PacketError> readReply(const Packet& packet);

} // namespace stellwerk::z21
