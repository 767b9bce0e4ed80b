// Config-data stream reassembly (command 0x21): header, data frames, CRC, inflate, line padding.
// Two modes, chosen by the first byte:
//  - frames: the rest is n x 13 network bytes fed to a receiver with a small limit. Invariant: no file
//    it accepts is larger than the limit, and inflate never exceeds it either.
//  - round trip: the rest is a file sent the way `stream encode` sends it (the key's format, or a
//    broadcast). Invariant: the receiver gives back exactly that file (`stream decode` round-trips).
#include "FuzzSupport.h"
#include "cs2config/ConfigStreamPayload.h"
#include "cs2config/ConfigStreamReceiver.h"
#include "cs2config/ConfigStreamSender.h"
#include "transport/NetworkFraming.h"

#include <array>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::cs2config;

namespace {

constexpr std::size_t Limit = 4096;

void checkOutcomes(const std::vector<StreamOutcome>& outcomes) {
    for (const StreamOutcome& outcome : outcomes)
        if (outcome)
            fuzz::check(outcome->contents.size() <= Limit, "a received file exceeds the limit");
}

void feedFrames(std::span<const std::uint8_t> bytes) {
    std::vector<can::CanFrame> frames;
    transport::decodeDatagram(bytes.first(bytes.size() / 13 * 13), frames);
    ConfigStreamReceiver receiver(StreamLimits{Limit});
    receiver.expectFile("loks", 0x4711);
    for (const can::CanFrame& frame : frames)
        checkOutcomes(receiver.feed(frame));
    if (auto outcome = receiver.finish())
        checkOutcomes({*outcome});
    const auto inflated = payload::inflate(bytes, Limit);
    if (inflated)
        fuzz::check(inflated->size() <= Limit && inflated->size() == payload::announcedSize(bytes),
                    "inflate exceeds its limit or the announced size");
}

// How `stream encode` may send a file: to a requester of a key (the key's format) or as a broadcast,
// which carries no key and leaves the receiver to tell the format from the bytes.
struct Sending {
    const char* key;
    bool broadcast;
};
constexpr std::array<Sending, 6> sendings = {{{"loks", false},
                                              {"lokinfo", false},
                                              {"lokdb", false},
                                              {"mags", false},
                                              {"loks", true},
                                              {"lokinfo", true}}};

// Whether the receiver can tell this file from what it gets: MS2 text without zero bytes (trailing
// zeros are frame padding there), and a broadcast plain file only when it is text that does not happen
// to be a valid compressed payload as well (binary without a key reads as a damaged compressed file).
bool unambiguous(StreamFormat format, bool broadcast, std::string_view contents) {
    if (format != StreamFormat::Ms2Text)
        return true;
    if (contents.find('\0') != std::string_view::npos)
        return false;
    const auto payload = streamPayload(contents, format);
    return !broadcast || (payload::isText(payload) && !payload::inflate(payload, std::size_t(16) << 20));
}

void roundTrip(std::uint8_t choice, std::string_view contents) {
    const Sending sending = sendings[choice % sendings.size()];
    const auto format = streamFormatForKey(sending.key);
    const auto address = sending.broadcast ? StreamAddress::broadcast(0x4711) : StreamAddress::reply(0x4711);
    ConfigStreamReceiver receiver;
    if (!sending.broadcast)
        receiver.expectFile(sending.key, 0x4711);
    std::vector<StreamOutcome> outcomes;
    for (const can::CanFrame& frame : streamFrames(contents, format, address))
        for (auto& outcome : receiver.feed(frame))
            outcomes.push_back(std::move(outcome));
    fuzz::check(outcomes.size() == 1, "a stream as sent does not give one outcome");
    if (!unambiguous(format, sending.broadcast, contents))
        return;
    fuzz::check(outcomes.front().hasValue(), "a stream as sent is not received",
                outcomes.front() ? std::string() : outcomes.front().error().message);
    fuzz::check(outcomes.front()->contents == contents, "the received file differs from the sent one",
                sending.key);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 16 * 1024)
        return -1;
    fuzz::FuzzInput input(data, size);
    const std::uint8_t mode = input.byte();
    if (mode & 0x80)
        roundTrip(mode, input.restText());
    else
        feedFrames(input.rest());
    return 0;
}
