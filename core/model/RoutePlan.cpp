#include "model/RoutePlan.h"

#include <QStringList>
#include <algorithm>

namespace stellwerk::model {
namespace {

// Expands one route into `plan`, keeping the chain of routes being expanded to find cycles.
class RouteExpander {
public:
    RouteExpander(const cs2config::RouteFile& routes, int maxDepth) : routes_(routes), maxDepth_(maxDepth) {}

    // A step's wait carries over to the next switching, so that a referencing step's wait delays the
    // first switching of the route it runs.
    QString expand(std::int64_t id, std::vector<RouteAction>& out) {
        const cs2config::Route* route = routes_.find(id);
        if (!route)
            return QStringLiteral("route %1 does not exist").arg(id);
        if (std::ranges::find(chain_, id) != chain_.end())
            return QStringLiteral("route %1 runs itself through %2").arg(id).arg(chainText());
        if (int(chain_.size()) >= maxDepth_)
            return QStringLiteral("routes nest deeper than %1 levels: %2").arg(maxDepth_).arg(chainText());
        chain_.push_back(id);
        for (const cs2config::RouteStep& step : route->steps) {
            carry_ += std::chrono::milliseconds(std::max<std::int64_t>(0, step.delayMs.value_or(0)));
            if (step.runsRoute()) {
                if (QString error = expand(step.routeReference, out); !error.isEmpty())
                    return error;
                continue;
            }
            if (step.accessory > 0) {
                out.push_back({step.accessory, int(step.position), carry_, id});
                carry_ = {};
            }
        }
        chain_.pop_back();
        return {};
    }

private:
    QString chainText() const {
        QStringList ids;
        for (const std::int64_t id : chain_)
            ids << QString::number(id);
        return ids.join(QStringLiteral(" -> "));
    }

    const cs2config::RouteFile& routes_;
    int maxDepth_;
    std::vector<std::int64_t> chain_;
    std::chrono::milliseconds carry_{0};
};

} // namespace

RoutePlan RoutePlan::of(const cs2config::RouteFile& routes, std::int64_t id, int maxDepth) {
    RoutePlan plan;
    plan.route = id;
    plan.error = RouteExpander(routes, maxDepth).expand(id, plan.actions);
    if (!plan.valid())
        plan.actions.clear();
    return plan;
}

std::map<std::int64_t, int> RoutePlan::finalPositions() const {
    std::map<std::int64_t, int> positions;
    for (const RouteAction& action : actions)
        positions[action.accessory] = action.position;
    return positions;
}

bool RoutePlan::standsIn(const std::function<std::optional<int>(std::int64_t accessory)>& positionOf) const {
    const std::map<std::int64_t, int> positions = finalPositions();
    return valid() && !positions.empty() && std::ranges::all_of(positions, [&](const auto& wanted) {
               return positionOf(wanted.first) == wanted.second;
           });
}

} // namespace stellwerk::model
