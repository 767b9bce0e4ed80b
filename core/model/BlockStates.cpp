#include "model/BlockStates.h"

#include "model/Commands.h"
#include "station/StationSession.h"

namespace stellwerk::model {

AnnouncedMeaning AnnouncedState::meaning() const {
    using cs2::AutomationState;
    switch (state.value_or(AutomationState::Error)) {
    case AutomationState::Deactivated:
        return AnnouncedMeaning::Deactivated;
    case AutomationState::Activated:
        return AnnouncedMeaning::Activated;
    case AutomationState::Running:
        return AnnouncedMeaning::Running;
    case AutomationState::BlockFree:
        return AnnouncedMeaning::Free;
    case AutomationState::BlockOccupied:
        return AnnouncedMeaning::Occupied;
    case AutomationState::Suspended:
    case AutomationState::Waiting:
        return AnnouncedMeaning::Waiting;
    case AutomationState::Reserved:
        return AnnouncedMeaning::Reserved;
    case AutomationState::Error:
        break;
    }
    return AnnouncedMeaning::Unknown;
}

BlockStates::BlockStates(station::StationSession& session, QObject* parent)
    : QObject(parent), session_(session) {
    connect(&session_, &station::StationSession::updated, this, &BlockStates::apply);
    connect(&session_, &station::StationSession::connectionLost, this, &BlockStates::forget);
    connect(&session_.liveness(), &station::Liveness::stationSilent, this, &BlockStates::forget);
}

void BlockStates::apply(const station::StationUpdates& updates) {
    QList<AutomationAddress> addresses;
    for (const station::AutomationAnnouncement& a : updates.automation) {
        const AutomationAddress address{a.device, a.function};
        AnnouncedState& entry = announced_[address];
        if (a.state) {
            entry.value = *a.state;
            entry.state = cs2::automationStateOf(*a.state);
        }
        if (a.loco)
            entry.loco = a.loco;
        latestOfFunction_[a.function] = address;
        if (!addresses.contains(address))
            addresses.push_back(address);
    }
    if (!addresses.isEmpty())
        emit changed(addresses);
}

// Another program's states are no longer known once the station is not heard.
void BlockStates::forget() {
    if (announced_.empty())
        return;
    QList<AutomationAddress> addresses;
    for (const auto& [address, state] : announced_)
        addresses.push_back(address);
    announced_.clear();
    latestOfFunction_.clear();
    emit changed(addresses);
}

std::optional<AnnouncedState> BlockStates::announcedAt(AutomationAddress address) const {
    const auto it = announced_.find(address);
    return it == announced_.end() ? std::nullopt : std::optional(it->second);
}

std::optional<AnnouncedState> BlockStates::blockState(int blockId) const {
    const auto address = addressOfBlock(blockId);
    return address ? announcedAt(*address) : std::nullopt;
}

std::optional<AnnouncedState> BlockStates::memoryState(cs2::MemoryFunction function) const {
    const auto it = latestOfFunction_.find(function.wire());
    return it == latestOfFunction_.end() ? std::nullopt : announcedAt(it->second);
}

namespace {

std::optional<cs2::MemoryFunction> slotOf(std::int64_t route) {
    return route < 1 || route > cs2::MemoryFunction::Count ? std::nullopt
                                                           : cs2::MemoryFunction::fromNumber(int(route));
}

} // namespace

QString BlockStates::memorySlotOfRoute(std::int64_t route) {
    const auto slot = slotOf(route);
    return slot ? QString::fromStdString(slot->text()) : QString();
}

std::optional<AnnouncedState> BlockStates::routeState(std::int64_t route) const {
    const auto slot = slotOf(route);
    return slot ? memoryState(*slot) : std::nullopt;
}

bool BlockStates::requestRoute(std::int64_t route, bool activate) {
    const auto slot = slotOf(route);
    return slot && requestMemoryFunction(*slot, activate);
}

std::optional<AutomationAddress> BlockStates::addressOfBlock(int blockId) {
    const auto slot = cs2::MemoryFunction::fromNumber(blockId);
    return slot ? std::optional(AutomationAddress{StellwerkDevice, slot->wire()}) : std::nullopt;
}

std::uint8_t BlockStates::statusValue(BlockState state) {
    using cs2::AutomationState;
    switch (state) {
    case BlockState::Free:
        return std::uint8_t(AutomationState::BlockFree);
    case BlockState::Occupied:
        return std::uint8_t(AutomationState::BlockOccupied);
    case BlockState::Reserved:
        return std::uint8_t(AutomationState::Reserved);
    case BlockState::Waiting:
        return std::uint8_t(AutomationState::Suspended);
    case BlockState::Unknown:
        break;
    }
    return std::uint8_t(AutomationState::Error);
}

bool BlockStates::announce(int blockId, BlockState state) {
    const auto address = addressOfBlock(blockId);
    if (!address)
        return false;
    if (!session_.send(
            commands::announceAutomationState(address->device, address->function, statusValue(state))))
        return false;
    own_[blockId] = state;
    return true;
}

std::optional<BlockState> BlockStates::ownState(int blockId) const {
    const auto it = own_.find(blockId);
    return it == own_.end() ? std::nullopt : std::optional(it->second);
}

bool BlockStates::requestMemoryFunction(cs2::MemoryFunction function, bool activate) {
    return session_.send(commands::requestMemoryFunction(MasterDevice, function.wire(), activate));
}

} // namespace stellwerk::model
