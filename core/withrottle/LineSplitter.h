#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::withrottle {

// Cuts a WiThrottle TCP stream into lines: a line ends at \n, \r or \r\n (JMRI's protocol page: "any
// newline sequence"), a partial line waits for the next bytes, and a line longer than the cap is dropped
// whole and counted, so a client that never sends a newline cannot grow the buffer. Empty lines (the \n
// of a \r\n that arrives in the next segment) are no lines.
class LineSplitter {
public:
    static constexpr std::size_t DefaultMaxLineLength = 1024;

    explicit LineSplitter(std::size_t maxLineLength = DefaultMaxLineLength) : maxLineLength_(maxLineLength) {}

    // The lines that bytes complete, in order, without their line ends.
    std::vector<std::string> feed(std::string_view bytes);

    std::size_t overlongLines() const { return overlongLines_; }
    std::size_t bufferedBytes() const { return partial_.size(); }

private:
    void take(char c, std::vector<std::string>& lines);

    std::size_t maxLineLength_;
    std::string partial_;
    bool discarding_ = false;
    std::size_t overlongLines_ = 0;
};

} // namespace stellwerk::withrottle
