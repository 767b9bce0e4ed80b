#include "sim/MemoryFunctions.h"

#include "cs2/Automation.h"
#include "cs2config/AccessoryType.h"
#include "sim/AccessoryCommands.h"

#include <algorithm>
#include <utility>

namespace stellwerk::sim {
namespace {

constexpr std::uint32_t MmBase = 0x3000;
constexpr int OutputsPerAddress = 2;

cs2::AutomationSwitch status(const cs2::AutomationSwitch& request, cs2::AutomationState state) {
    return {request.device, request.function, std::uint8_t(state), 0, std::nullopt};
}

} // namespace

MemoryFunctions::MemoryFunctions(const StationLayout& layout, StationState& state, Later later)
    : layout_(layout), state_(state), later_(std::move(later)) {}

bool MemoryFunctions::handle(const cs2::Message& m, Outbox& out) {
    const auto* request = std::get_if<cs2::AutomationSwitch>(&m.body);
    if (!request)
        return false;
    if (request->loco || (request->device != 0 && request->device != state_.deviceId))
        return true; // a block's locomotive, or another device's memory
    if (request->position == 0) {
        out.respond(status(*request, cs2::AutomationState::Deactivated), m.prio);
        return true;
    }
    const auto slot = cs2::MemoryFunction::fromWire(request->function);
    if (!slot || !layout_.routes().find(slot->number())) {
        out.respond(status(*request, cs2::AutomationState::Error), m.prio);
        return true;
    }
    out.respond(status(*request, cs2::AutomationState::Running), m.prio);
    std::vector<Switching> steps;
    std::chrono::milliseconds carry{0};
    if (!expand(slot->number(), 0, carry, steps)) {
        out.respond(status(*request, cs2::AutomationState::Error), m.prio);
        return true;
    }
    run(*request, std::move(steps), out);
    return true;
}

// A step's wait carries over to the next switching, so that a referencing step's wait delays the first
// switching of the route it runs.
bool MemoryFunctions::expand(std::int64_t id, int depth, std::chrono::milliseconds& carry,
                             std::vector<Switching>& out) const {
    const cs2config::Route* route = layout_.routes().find(id);
    if (!route || depth >= MaxDepth)
        return false;
    for (const cs2config::RouteStep& step : route->steps) {
        carry += std::chrono::milliseconds(std::max<std::int64_t>(0, step.delayMs.value_or(0)));
        if (step.runsRoute()) {
            if (!expand(step.routeReference, depth + 1, carry, out))
                return false;
        } else if (step.accessory > 0) {
            Switching next = switching(step.accessory, step.position);
            next.after = std::exchange(carry, std::chrono::milliseconds{0});
            out.push_back(next);
        }
    }
    return true;
}

// Switches the steps without a wait now, and the rest one after the other, each after its wait; the last
// one announces the route activated.
void MemoryFunctions::run(const cs2::AutomationSwitch& request, std::vector<Switching> steps, Outbox& out) {
    std::size_t next = 0;
    while (next < steps.size() && steps[next].after.count() == 0)
        switchNow(steps[next++], out);
    if (next == steps.size()) {
        out.respond(status(request, cs2::AutomationState::Activated));
        return;
    }
    const std::chrono::milliseconds wait = steps[next].after;
    steps[next].after = std::chrono::milliseconds{0};
    steps.erase(steps.begin(), steps.begin() + std::ptrdiff_t(next));
    later_(wait, [this, request, steps = std::move(steps)](Outbox& later) mutable {
        run(request, std::move(steps), later);
    });
}

// As the keyboard switches it: the output on, which the track format processor confirms on the bus.
void MemoryFunctions::switchNow(const Switching& step, Outbox& out) {
    state_.accessories[step.locId] = step.position;
    out.respond(cs2::AccessorySwitch{cs2::LocId(step.locId), step.position, 1, std::nullopt});
}

// The wire address and output of a keyboard number's position: an article with two addresses (three-way
// turnout, Hp0/1/2 signal) has positions 2 and 3 on the second one.
MemoryFunctions::Switching MemoryFunctions::switching(std::int64_t keyboardNumber,
                                                      std::int64_t position) const {
    std::uint32_t locId = MmBase + std::uint32_t(keyboardNumber) - 1;
    int addresses = 1;
    for (const cs2config::Accessory& accessory : layout_.accessories().accessories) {
        if (accessory.id != keyboardNumber)
            continue;
        locId = AccessoryCommands::locIdOf(accessory);
        if (const auto* type = cs2config::findAccessoryType(accessory.type))
            addresses = type->addresses;
    }
    if (addresses > 1) {
        locId += std::uint32_t(position / OutputsPerAddress);
        position %= OutputsPerAddress;
    }
    return {locId, std::uint8_t(position), std::chrono::milliseconds{0}};
}

} // namespace stellwerk::sim
