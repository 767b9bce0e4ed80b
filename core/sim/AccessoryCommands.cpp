#include "sim/AccessoryCommands.h"

namespace stellwerk::sim {
namespace {

constexpr std::uint32_t MmBase = 0x3000, DccBase = 0x3800;
constexpr std::uint8_t OnOffPositions = 2;

} // namespace

AccessoryCommands::AccessoryCommands(const StationLayout& layout, StationState& state) : state_(state) {
    for (const cs2config::Accessory& accessory : layout.accessories().accessories)
        if (accessory.id >= 1)
            state_.accessories[locIdOf(accessory)] = std::uint8_t(accessory.position);
}

std::uint32_t AccessoryCommands::locIdOf(const cs2config::Accessory& accessory) {
    const std::uint32_t base = accessory.protocol == "dcc" ? DccBase : MmBase;
    return base + std::uint32_t(accessory.id) - 1;
}

bool AccessoryCommands::handle(const cs2::Message& m, Outbox& out) {
    const auto* command = std::get_if<cs2::AccessorySwitch>(&m.body);
    if (!command)
        return false;
    const cs2::Protocol protocol = command->article.protocol();
    if (!command->article.isAccessory())
        return true; // not an accessory decoder: nothing on the track takes it
    const bool onOffOnly = protocol == cs2::Protocol::DccAccessory || protocol == cs2::Protocol::Sx1Accessory;
    if (onOffOnly && command->position >= OnOffPositions)
        return true; // 4.1: DCC and SX1 know positions 0 and 1 only
    if (command->current != 0)
        state_.accessories[command->article.value()] = command->position;
    out.respond(m.body, m.prio);
    return true;
}

} // namespace stellwerk::sim
