#pragma once

#include "busreading/BusContext.h"
#include "busreading/FrameDescription.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <unordered_map>

namespace stellwerk::ui {

// The descriptions of the rows looked at last, so that showing a row (five columns, several roles) and
// filtering it decode its frame once; only the visible part of a million-row history is ever described.
class FrameDescriptions {
public:
    static constexpr std::size_t Capacity = 1024;

    // The description of the row with this sequence number, whose frame came from a bus with `profile`
    // that has revealed `context` so far (null: nothing); valid until the next call.
    const busreading::FrameDescription& of(std::uint64_t sequence, const can::CanFrame& frame,
                                           const busreading::BusProfile& profile,
                                           const busreading::BusContext* context) const;
    void clear() const;
    // How many frames were decoded so far (for tests: each row once while it stays in the cache).
    std::uint64_t decodeCount() const { return m_decodes; }

private:
    mutable std::unordered_map<std::uint64_t, busreading::FrameDescription> m_entries;
    mutable std::deque<std::uint64_t> m_order;
    mutable std::uint64_t m_decodes = 0;
};

} // namespace stellwerk::ui
