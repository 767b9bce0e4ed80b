#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace stellwerk::automation {

// A train's way from the block its front stands in to its destination: the connections in order, and the
// block each of them leads into (the last one is the destination).
struct Path {
    std::vector<int> connections;
    std::vector<int> blocks;
    // Every turnout on the way (keyboard number, position), in the order passed.
    std::vector<std::pair<std::int64_t, int>> turnouts;

    bool empty() const { return blocks.empty(); }
    int destination() const { return blocks.empty() ? 0 : blocks.back(); }
};

} // namespace stellwerk::automation
