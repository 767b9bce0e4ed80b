#pragma once

#include "base/Expected.h"
#include "z21/Packet.h"
#include "z21/Requests.h"

#include <cstdint>
#include <span>
#include <vector>

namespace stellwerk::z21 {

// The requests of one datagram in order, and what was wrong with the packets that are none: a wrong
// length or a datagram cut short never throws and never stops the requests read before it.
struct DatagramRequests {
    std::vector<Request> requests;
    std::vector<PacketError> errors;
};
DatagramRequests readRequests(std::span<const std::uint8_t> datagram);

// One framed packet as a request: a known command of the wrong length is an error; a packet of an unknown
// header or X-header, or with a value the specification does not allow (a format other than 0 or 1, a
// function action 11 or a function above F31), is an UnknownRequest.
Expected<Request, PacketError> readRequest(const Packet& packet);

// A request as its packet, with the right XOR byte (what a client sends; for tests and test clients).
std::vector<std::uint8_t> encodeRequest(const RequestBody& request);

} // namespace stellwerk::z21
