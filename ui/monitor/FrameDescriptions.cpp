#include "monitor/FrameDescriptions.h"

namespace stellwerk::ui {

const busreading::FrameDescription& FrameDescriptions::of(std::uint64_t sequence, const can::CanFrame& frame,
                                                          const busreading::BusProfile& profile,
                                                          const busreading::BusContext* context) const {
    if (const auto found = m_entries.find(sequence); found != m_entries.end())
        return found->second;
    if (m_order.size() >= Capacity) {
        m_entries.erase(m_order.front());
        m_order.pop_front();
    }
    ++m_decodes;
    m_order.push_back(sequence);
    return m_entries.emplace(sequence, busreading::FrameDescription(frame, profile, context)).first->second;
}

void FrameDescriptions::clear() const {
    m_entries.clear();
    m_order.clear();
}

} // namespace stellwerk::ui
