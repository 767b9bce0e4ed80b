#include "model/OccupantBook.h"

#include "model/Railway.h"

namespace stellwerk::model {

void OccupantBook::setRailway(Railway* railway) {
    m_railway = railway;
    if (!railway)
        return;
    for (const auto& [key, locId] : m_occupants)
        railway->reportOccupant(key, locId);
}

void OccupantBook::report(ContactKey key, std::uint32_t locId) {
    if (locId == 0)
        m_occupants.erase(key);
    else
        m_occupants[key] = locId;
    if (m_railway)
        m_railway->reportOccupant(key, locId);
}

void OccupantBook::clear() {
    if (m_railway)
        for (const auto& [key, locId] : m_occupants)
            m_railway->reportOccupant(key, 0);
    m_occupants.clear();
}

std::uint32_t OccupantBook::occupantOf(ContactKey key) const {
    const auto it = m_occupants.find(key);
    return it == m_occupants.end() ? 0 : it->second;
}

} // namespace stellwerk::model
