// 13-byte network framing of a TCP byte stream: the bytes arrive cut into arbitrary segments.
// Invariants: FrameAssembler yields the same frames as reading the whole stream at once
// (decodeDatagram), whatever the segmentation; what waits is the incomplete rest; every frame it
// hands on is well formed and writes back to the bytes it came from.
#include "FuzzSupport.h"
#include "can/FrameText.h"
#include "transport/FrameAssembler.h"
#include "transport/NetworkFraming.h"

#include <vector>

using namespace stellwerk;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::FuzzInput input(data, size);
    // Segment lengths come first (one byte each, 0 ends the list), then the stream itself.
    std::vector<std::size_t> cuts;
    for (std::uint8_t cut = input.byte(); cut != 0 && cuts.size() < 64; cut = input.byte())
        cuts.push_back(cut);
    const auto stream = input.rest();

    transport::FrameAssembler assembler;
    std::vector<can::CanFrame> assembled;
    std::size_t malformed = 0;
    std::size_t at = 0;
    for (std::size_t i = 0; at < stream.size(); ++i) {
        const std::size_t length =
            cuts.empty() ? stream.size() : std::min(cuts[i % cuts.size()], stream.size() - at);
        malformed += assembler.feed(stream.subspan(at, length), assembled);
        at += length;
    }

    const std::size_t whole = stream.size() / can::CanFrame::NetworkSize * can::CanFrame::NetworkSize;
    std::vector<can::CanFrame> direct;
    const auto content = transport::decodeDatagram(stream.first(whole), direct);
    fuzz::check(assembler.pendingBytes() == stream.size() - whole, "the assembler keeps the wrong rest");
    fuzz::check(assembled.size() == direct.size() && malformed == content.malformed,
                "segmentation changes which frames arrive");
    for (std::size_t i = 0; i < assembled.size(); ++i) {
        fuzz::check(assembled[i] == direct[i], "segmentation changes a frame",
                    can::formatDocument(assembled[i]));
        fuzz::check(assembled[i].isWellFormed(), "a malformed frame was handed on",
                    can::formatDocument(assembled[i]));
    }
    const QByteArray again = transport::encodeFrames(assembled);
    std::vector<can::CanFrame> reread;
    transport::decodeDatagram(transport::asBytes(again), reread);
    fuzz::check(reread.size() == assembled.size(), "frames written back do not read back");
    for (std::size_t i = 0; i < reread.size(); ++i)
        fuzz::check(reread[i] == assembled[i], "a frame written back reads differently");
    return 0;
}
