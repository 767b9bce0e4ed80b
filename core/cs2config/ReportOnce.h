#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>

namespace stellwerk::cs2config {

// Remembers the subjects (an unknown key, type, record or message) a reader has reported, so that a
// file with 127 records holding the same unknown key makes one report, not 127.
class ReportOnce {
public:
    // True the first time this subject is seen.
    bool first(std::string_view subject) { return see(subject).second; }
    // The subject's number in the order subjects were first seen (0, 1, ...), and whether this is
    // the first time, for a caller that keeps one entry per subject and counts the repeats.
    std::pair<std::size_t, bool> see(std::string_view subject);

private:
    std::map<std::string, std::size_t, std::less<>> seen_;
};

} // namespace stellwerk::cs2config
