#include "withrottle/LineSplitter.h"

namespace stellwerk::withrottle {

std::vector<std::string> LineSplitter::feed(std::string_view bytes) {
    std::vector<std::string> lines;
    for (const char c : bytes)
        take(c, lines);
    return lines;
}

void LineSplitter::take(char c, std::vector<std::string>& lines) {
    if (c == '\n' || c == '\r') {
        if (!discarding_ && !partial_.empty())
            lines.push_back(std::move(partial_));
        partial_.clear();
        discarding_ = false;
        return;
    }
    if (discarding_)
        return;
    if (partial_.size() >= maxLineLength_) {
        partial_.clear();
        discarding_ = true;
        ++overlongLines_;
        return;
    }
    partial_.push_back(c);
}

} // namespace stellwerk::withrottle
