#include "cs2config/RouteAccessoryCheck.h"

#include <map>
#include <string>

namespace stellwerk::cs2config {

namespace {

using AccessoriesById = std::multimap<std::int64_t, const Accessory*>;

bool switchesAccessory(const RouteStep& step) {
    return !step.runsRoute() && step.accessory > 0 &&
           (step.type.empty() || step.type == RouteStep::accessoryType);
}

// Unknown types take any position; two one-output articles on one id take what either takes.
bool positionFits(const AccessoriesById& byId, std::int64_t id, std::int64_t position,
                  const AccessoryTypeInfo*& shown) {
    const auto [from, to] = byId.equal_range(id);
    for (auto it = from; it != to; ++it) {
        const AccessoryTypeInfo* type = it->second->typeInfo();
        if (!type || type->acceptsPosition(position))
            return true;
        shown = type;
    }
    return false;
}

void checkStep(const Route& route, const RouteStep& step, const AccessoriesById& byId,
               Diagnostics& diagnostics) {
    const std::string where =
        "route " + std::to_string(route.id) + " switches accessory " + std::to_string(step.accessory);
    if (!byId.contains(step.accessory)) {
        diagnostics.warning(step.lineNumber(), where + ", which magnetartikel.cs2 does not have", "kept");
        return;
    }
    const AccessoryTypeInfo* type = nullptr;
    if (!positionFits(byId, step.accessory, step.position, type))
        diagnostics.warning(step.lineNumber(),
                            where + " to position " + std::to_string(step.position) + ", which " +
                                std::string(type->key) + " does not have",
                            "kept");
}

} // namespace

void checkRouteAccessories(const RouteFile& routes, const AccessoryFile& accessories,
                           Diagnostics& diagnostics) {
    AccessoriesById byId;
    for (const Accessory& accessory : accessories.accessories)
        byId.emplace(accessory.id, &accessory);
    for (const Route& route : routes.routes)
        for (const RouteStep& step : route.steps)
            if (switchesAccessory(step))
                checkStep(route, step, byId, diagnostics);
}

} // namespace stellwerk::cs2config
