// A UDP datagram of a Z21 client (or, with the first byte odd, of a Z21 server): the rest of the input.
// Invariants: reading never crashes; the packets are framed back to back inside the datagram, and without
// a framing error they end where it ends; every packet is a request (or reply) or one error; every request
// and reply read is written as a packet whose DataLen is its size, whose X-bus XOR is right, and which
// reads back as the same value (an unknown request's data only while it was kept whole).
#include "FuzzSupport.h"
#include "z21/ReplyCodec.h"
#include "z21/RequestCodec.h"

#include <string>

using namespace stellwerk;

namespace {

using Bytes = std::vector<std::uint8_t>;

// `known`: a request or reply the codec understood, written by it (an unknown one is written back as it
// came, its XOR byte too, so that it reads back as itself).
void checkPacketBytes(const Bytes& bytes, bool known = true) {
    fuzz::check(bytes.size() >= 4 && (bytes[0] | (bytes[1] << 8)) == int(bytes.size()),
                "a written packet's DataLen is not its size");
    if (known && bytes[2] == z21::XBusHeader && bytes[3] == 0)
        fuzz::check(z21::xorOf(std::span(bytes).subspan(4)) == 0,
                    "a written X-bus packet has a wrong XOR byte");
}

void checkFraming(std::span<const std::uint8_t> datagram, const z21::Framing& framing) {
    std::size_t end = 0;
    for (const z21::Packet& packet : framing.packets) {
        fuzz::check(packet.offset == end, "packets are not framed back to back");
        end = packet.offset + 4 + packet.data.size();
        fuzz::check(end <= datagram.size(), "a packet reaches beyond the datagram");
    }
    fuzz::check(framing.errors.size() <= 1, "more than one framing error");
    fuzz::check(!framing.errors.empty() || end == datagram.size(), "the packets end before the datagram");
}

void checkRequests(std::span<const std::uint8_t> datagram, std::size_t packets) {
    const z21::DatagramRequests read = z21::readRequests(datagram);
    std::size_t wrongLengths = 0;
    for (const z21::PacketError& error : read.errors)
        wrongLengths += error.problem == z21::PacketProblem::WrongLength;
    fuzz::check(read.requests.size() + wrongLengths == packets, "a packet is neither a request nor an error");
    for (const z21::Request& request : read.requests) {
        const auto* unknown = std::get_if<z21::UnknownRequest>(&request.body);
        if (unknown && unknown->data.size() >= 64)
            continue;
        const Bytes bytes = z21::encodeRequest(request.body);
        checkPacketBytes(bytes, unknown == nullptr);
        const z21::DatagramRequests again = z21::readRequests(bytes);
        fuzz::check(again.requests.size() == 1 && again.errors.empty() &&
                        again.requests[0].body == request.body,
                    "a request does not read back as itself");
    }
}

void checkReplies(std::span<const std::uint8_t> datagram, std::size_t packets) {
    const z21::DatagramReplies read = z21::readReplies(datagram);
    fuzz::check(read.replies.size() <= packets, "more replies than packets");
    for (const z21::Reply& reply : read.replies) {
        const Bytes bytes = z21::encodeReply(reply);
        checkPacketBytes(bytes);
        const z21::DatagramReplies again = z21::readReplies(bytes);
        fuzz::check(again.replies.size() == 1 && again.errors.empty() && again.replies[0] == reply,
                    "a reply does not read back as itself");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 4096)
        return -1;
    fuzz::FuzzInput input(data, size);
    const bool asReplies = (input.byte() & 1) != 0;
    const auto datagram = input.rest();
    const z21::Framing framing = z21::frameDatagram(datagram);
    checkFraming(datagram, framing);
    if (asReplies)
        checkReplies(datagram, framing.packets.size());
    else
        checkRequests(datagram, framing.packets.size());
    return 0;
}
