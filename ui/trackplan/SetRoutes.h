#pragma once

#include <cstdint>
#include <set>

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// Which routes stand set (every accessory where the route leaves it, as the station confirmed) and which
// accessories they hold, so that the plan can draw a set route: its button ringed and its turnouts and
// signals in the highlight colour.
class SetRoutes final {
public:
    // Works the sets out again; true when they changed (the plan then repaints).
    bool update(const model::Railway* railway);
    bool isSet(std::int64_t route) const { return m_routes.contains(route); }
    bool holds(std::int64_t accessory) const { return m_accessories.contains(accessory); }

private:
    std::set<std::int64_t> m_routes;
    std::set<std::int64_t> m_accessories;
};

} // namespace stellwerk::ui
