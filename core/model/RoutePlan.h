#pragma once

#include "cs2config/RouteFile.h"

#include <QString>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::model {

// One accessory switching of a route, after a wait, with the route it comes from (a nested route's
// steps run in place of the step that references it).
struct RouteAction {
    std::int64_t accessory = 0;
    int position = 0;
    std::chrono::milliseconds delay{0};
    std::int64_t route = 0;
};

// A route flattened into the accessory switchings it makes, in order; nested route references are
// expanded, and a route that (directly or indirectly) references itself is refused.
struct RoutePlan {
    std::int64_t route = 0;
    std::vector<RouteAction> actions;
    QString error; // empty when the plan can run

    bool valid() const { return error.isEmpty(); }
    // The position each accessory is left in (its last switching in the plan), by keyboard id.
    std::map<std::int64_t, int> finalPositions() const;
    // True when the plan switches something and every accessory it switches stands where the plan leaves
    // it (`positionOf`: the confirmed position, nullopt when not known): the route is set.
    bool standsIn(const std::function<std::optional<int>(std::int64_t accessory)>& positionOf) const;

    // The plan of route `id` in `routes`: an error for a missing route, a reference cycle or a nesting
    // deeper than `maxDepth`.
    static RoutePlan of(const cs2config::RouteFile& routes, std::int64_t id, int maxDepth = 16);
};

} // namespace stellwerk::model
