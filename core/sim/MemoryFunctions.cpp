#include "sim/MemoryFunctions.h"

#include "cs2/Automation.h"
#include "cs2config/AccessoryType.h"
#include "sim/AccessoryCommands.h"

namespace stellwerk::sim {
namespace {

constexpr std::uint32_t MmBase = 0x3000;
constexpr int OutputsPerAddress = 2;

cs2::AutomationSwitch status(const cs2::AutomationSwitch& request, cs2::AutomationState state) {
    return {request.device, request.function, std::uint8_t(state), 0, std::nullopt};
}

} // namespace

MemoryFunctions::MemoryFunctions(const StationLayout& layout, StationState& state)
    : layout_(layout), state_(state) {}

bool MemoryFunctions::handle(const cs2::Message& m, Outbox& out) {
    const auto* request = std::get_if<cs2::AutomationSwitch>(&m.body);
    if (!request)
        return false;
    if (request->loco || (request->device != 0 && request->device != state_.deviceId))
        return true; // a block's locomotive, or another device's memory
    const auto slot = cs2::MemoryFunction::fromWire(request->function);
    if (request->position == 0) {
        out.respond(status(*request, cs2::AutomationState::Deactivated), m.prio);
        return true;
    }
    if (!slot || !layout_.routes().find(slot->number())) {
        out.respond(status(*request, cs2::AutomationState::Error), m.prio);
        return true;
    }
    out.respond(status(*request, cs2::AutomationState::Running), m.prio);
    const bool ran = run(slot->number(), 0, out);
    out.respond(status(*request, ran ? cs2::AutomationState::Activated : cs2::AutomationState::Error),
                m.prio);
    return true;
}

bool MemoryFunctions::run(std::int64_t id, int depth, Outbox& out) {
    const cs2config::Route* route = layout_.routes().find(id);
    if (!route || depth >= MaxDepth)
        return false;
    for (const cs2config::RouteStep& step : route->steps) {
        if (step.runsRoute()) {
            if (!run(step.routeReference, depth + 1, out))
                return false;
        } else if (step.accessory > 0) {
            switchAccessory(step.accessory, step.position, out);
        }
    }
    return true;
}

// As the keyboard switches it: the output on, which the track format processor confirms on the bus. An
// article with two addresses (three-way turnout, Hp0/1/2 signal) has positions 2 and 3 on the second one.
void MemoryFunctions::switchAccessory(std::int64_t keyboardNumber, std::int64_t position, Outbox& out) {
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
    state_.accessories[locId] = std::uint8_t(position);
    out.respond(cs2::AccessorySwitch{cs2::LocId(locId), std::uint8_t(position), 1, std::nullopt});
}

} // namespace stellwerk::sim
