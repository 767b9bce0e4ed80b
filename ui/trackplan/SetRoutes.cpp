#include "trackplan/SetRoutes.h"

#include "model/Railway.h"
#include "model/RoutePlan.h"

namespace stellwerk::ui {

bool SetRoutes::update(const model::Railway* railway) {
    std::set<std::int64_t> routes;
    std::set<std::int64_t> accessories;
    if (railway && railway->isStateReported())
        for (const model::Route& route : railway->state().routes().items())
            if (!route.running() && railway->isRouteSet(route.id())) {
                routes.insert(route.id());
                for (const auto& [accessory, position] :
                     model::RoutePlan::of(railway->state().routeFile(), route.id()).finalPositions())
                    accessories.insert(accessory);
            }
    const bool changed = routes != m_routes || accessories != m_accessories;
    m_routes = std::move(routes);
    m_accessories = std::move(accessories);
    return changed;
}

} // namespace stellwerk::ui
