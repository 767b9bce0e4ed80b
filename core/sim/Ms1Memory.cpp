#include "sim/Ms1Memory.h"

#include "mcan/Codec.h"

#include <algorithm>

namespace stellwerk::sim {

Ms1Loco* Ms1Memory::loco(std::uint16_t handle) {
    const auto index = indexOf(handle);
    return index ? &stack[*index] : nullptr;
}

std::optional<std::size_t> Ms1Memory::indexOf(std::uint16_t handle) const {
    const auto found = std::ranges::find(stack, handle, &Ms1Loco::handle);
    if (found == stack.end())
        return std::nullopt;
    return std::size_t(found - stack.begin());
}

std::uint8_t Ms1Memory::statusIndexOf(std::uint8_t type) const {
    for (const auto& [index, known] : statusTypes)
        if (known == type)
            return index;
    return type;
}

void Ms1Memory::setStatus(std::uint8_t index, std::uint8_t value) {
    const auto known = statusTypes.find(index);
    const std::uint8_t type = known != statusTypes.end() ? known->second : index;
    if (type == 1)
        stopped = value != 0;
    else if (type == 2)
        shortCircuit = value != 0;
}

void Ms1Outbox::send(const mcan::Message& message) {
    frames.push_back(mcan::encode(message));
}

} // namespace stellwerk::sim
