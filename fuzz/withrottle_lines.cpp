// A WiThrottle TCP stream: the first byte sets the line cap (8..263), the second where the stream is cut
// in two segments, the rest is the stream. Invariants: the lines do not depend on how the stream is cut
// (whole, in two, byte by byte); no line is empty, longer than the cap or holds a line end, and the buffer
// stays within the cap; every line reads as a client message and as a server line (or none) without
// crashing; a message or line read formats to a line without line ends that reads back as the same kind
// of message and formats the same again (formatting is stable; texts are cleaned once).
#include "FuzzSupport.h"
#include "withrottle/LineSplitter.h"
#include "withrottle/ServerLines.h"

#include <string>

using namespace stellwerk;

namespace {

using Lines = std::vector<std::string>;

void checkLineText(const std::string& line, const char* what) {
    fuzz::check(line.find('\n') == std::string::npos && line.find('\r') == std::string::npos, what, line);
}

void checkClientLine(const std::string& line) {
    const withrottle::ClientMessage message = withrottle::parseClientLine(line);
    const std::string formatted = withrottle::formatClientLine(message);
    checkLineText(formatted, "a formatted client line holds a line end");
    const withrottle::ClientMessage again = withrottle::parseClientLine(formatted);
    fuzz::check(again.index() == message.index() || formatted.empty(),
                "a formatted client message reads as another kind", line);
    fuzz::check(withrottle::formatClientLine(again) == formatted || formatted.empty(),
                "formatting a client message is not stable", line);
}

void checkServerLine(const std::string& line) {
    const auto parsed = withrottle::parseServerLine(line);
    if (!parsed)
        return;
    const std::string formatted = withrottle::formatServerLine(*parsed);
    checkLineText(formatted, "a formatted server line holds a line end");
    const auto again = withrottle::parseServerLine(formatted);
    fuzz::check(again.has_value() && again->index() == parsed->index(),
                "a formatted server line does not read back", line);
    fuzz::check(withrottle::formatServerLine(*again) == formatted, "formatting a server line is not stable",
                line);
}

Lines splitInPieces(std::string_view stream, std::size_t cap, std::size_t cut) {
    withrottle::LineSplitter splitter(cap);
    Lines lines = splitter.feed(stream.substr(0, cut));
    for (std::string& line : splitter.feed(stream.substr(cut)))
        lines.push_back(std::move(line));
    fuzz::check(splitter.bufferedBytes() <= cap, "the line buffer grew beyond its cap");
    return lines;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 8192)
        return -1;
    fuzz::FuzzInput input(data, size);
    const std::size_t cap = 8 + input.byte();
    const std::uint8_t cutByte = input.byte();
    const std::string_view rest = input.restText();
    const std::size_t cut = cutByte % (rest.size() + 1);
    const Lines whole = withrottle::LineSplitter(cap).feed(rest);
    fuzz::check(splitInPieces(rest, cap, cut) == whole, "the lines depend on where the stream is cut");
    withrottle::LineSplitter byteByByte(cap);
    Lines single;
    for (const char c : rest)
        for (std::string& line : byteByByte.feed({&c, 1}))
            single.push_back(std::move(line));
    fuzz::check(single == whole, "the lines differ when the stream comes byte by byte");
    for (const std::string& line : whole) {
        fuzz::check(!line.empty() && line.size() <= cap, "a line is empty or longer than the cap", line);
        checkLineText(line, "a line holds a line end");
        checkClientLine(line);
        checkServerLine(line);
    }
    return 0;
}
