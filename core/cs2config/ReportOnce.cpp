#include "cs2config/ReportOnce.h"

namespace stellwerk::cs2config {

std::pair<std::size_t, bool> ReportOnce::see(std::string_view subject) {
    if (const auto found = seen_.find(subject); found != seen_.end())
        return {found->second, false};
    const std::size_t number = seen_.size();
    seen_.emplace(std::string(subject), number);
    return {number, true};
}

} // namespace stellwerk::cs2config
