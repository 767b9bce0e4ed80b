// Every frame notation the CLI reads (document, candump, bracketed logs, 26 hex digits), one line.
// Invariants: a frame that was read prints in document notation (as `decode` does) and reads back to
// the same frame, and a well-formed one in every other notation too; `decode --json` writes one valid
// JSON object per line whatever the bytes of the input.
#include "DecodeCommand.h"
#include "FuzzSupport.h"
#include "can/FrameText.h"

#include <sstream>

using namespace stellwerk;
using namespace stellwerk::can;

namespace {

void checkReadsBack(const CanFrame& frame, const std::string& text) {
    const auto again = can::parseFrame(text);
    fuzz::check(again.hasValue(), "a printed frame cannot be read back",
                text + (again ? "" : ": " + again.error()));
    fuzz::check(again->frame == frame, "a printed frame reads back differently", text);
}

void checkJsonOutput(std::string_view line) {
    std::istringstream in{std::string(line)};
    std::ostringstream out, err;
    cli::runDecode({"--json"}, in, out, err);
    std::istringstream lines(out.str());
    for (std::string json; std::getline(lines, json);)
        fuzz::check(fuzz::isJsonDocument(json, false), "decode --json wrote a line that is not JSON", json);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 512)
        return -1;
    const std::string_view line(reinterpret_cast<const char*>(data), size);
    checkJsonOutput(line);
    const auto parsed = can::parseFrame(line);
    if (!parsed)
        return 0;
    const CanFrame& frame = parsed->frame;
    fuzz::check((frame.id & ~frame.idMask()) == 0, "an identifier wider than its format was read",
                std::string(line));
    if (parsed->notation == FrameNotation::Network || parsed->notation == FrameNotation::Candump)
        fuzz::check(frame.dlc <= 8, "a DLC above 8 was read from the network or candump notation",
                    std::string(line));
    checkReadsBack(frame, formatDocument(frame));
    if (!frame.isWellFormed())
        return 0;
    checkReadsBack(frame, formatCandump(frame));
    if (frame.fitsNetworkForm()) // the network form carries extended frames only
        checkReadsBack(frame, formatNetwork(frame));
    return 0;
}
