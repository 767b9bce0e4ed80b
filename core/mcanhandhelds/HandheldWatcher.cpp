#include "mcanhandhelds/HandheldWatcher.h"

#include <type_traits>

namespace stellwerk::mcanhandhelds {
namespace {

// A handheld is dropped by its master after 30 master polls a second apart (7.2.2).
constexpr std::chrono::seconds DroppedAfterSilence{30};

std::uint8_t pairOf(const can::CanFrame& frame) {
    return std::uint8_t((frame.id & 0x7F) | 1);
}

} // namespace

bool HandheldWatcher::observe(const can::CanFrame& frame, Clock::time_point now) {
    const mcan::Message message = roles_.observe(frame);
    if (const auto* grant = std::get_if<mcan::LoginGrant>(&message)) {
        Watched& watched = watched_[grant->node | 1];
        watched.handheld = Handheld{};
        watched.handheld.uid = grant->slaveUid;
        watched.handheld.slaveNode = std::uint8_t(grant->node | 1);
        watched.handheld.state = HandheldState::Upgrading;
        watched.handheld.ours = false;
        watched.lastHeard = now;
        return true;
    }
    if (mcan::layoutOf(frame.id) != mcan::Layout::Session)
        return false;
    const auto found = watched_.find(pairOf(frame));
    if (found == watched_.end())
        return false;
    Watched& watched = found->second;
    if (mcan::isSlaveNode(std::uint8_t(frame.id & 0x7F)))
        watched.lastHeard = now;
    const bool slaveChanged = observeSlave(watched, message);
    return observeLoco(watched, message) || slaveChanged;
}

bool HandheldWatcher::observeSlave(Watched& watched, const mcan::Message& message) {
    Handheld& handheld = watched.handheld;
    bool changed = false;
    if (std::holds_alternative<mcan::Poll>(message) && handheld.state != HandheldState::Online) {
        handheld.state = HandheldState::Online;
        changed = true;
    }
    const QString name = QString::fromStdString(roles_.slaveName(handheld.slaveNode));
    if (!name.isEmpty() && name != handheld.name) {
        handheld.name = name;
        changed = true;
    }
    if (const auto* size = std::get_if<mcan::StackSizeAnswer>(&message)) {
        handheld.stackSize = size->size;
        changed = true;
    }
    return changed;
}

// What the master granted, and how each locomotive of the handheld's stack runs: what it told the handheld
// during the upgrade and since. The handheld shows the values of the one it took.
bool HandheldWatcher::observeLoco(Watched& watched, const mcan::Message& message) {
    Handheld& handheld = watched.handheld;
    if (const auto* throttle = std::get_if<mcan::Throttle>(&message);
        throttle && !mcan::isSlaveNode(throttle->at.node) && throttle->at.prio == mcan::prio::Throttle) {
        const QString loco = QString::fromStdString(roles_.name(handheld.slaveNode, throttle->at.handle));
        handheld.locoRefused = throttle->state == 0xFFFF;
        handheld.locoName = throttle->state == 0x0008 ? loco : QString();
        watched.taken = throttle->state == 0x0008 ? std::optional(throttle->at.handle) : std::nullopt;
        showTaken(watched);
        return true;
    }
    const auto* value = std::get_if<mcan::FunctionValue>(&message);
    if (!value || roles_.role(handheld.slaveNode, value->at.handle) != mcan::HandleRole::Loco)
        return false;
    LocoValues& loco = watched.locos[value->at.handle];
    if (value->function == 1) {
        loco.speed = value->value & 0x7F;
        loco.forward = (value->value & 0x80) == 0;
    } else if (value->function >= 2 && value->function < 34) {
        const std::uint32_t bit = 1u << (value->function - 2);
        loco.functions = value->value ? loco.functions | bit : loco.functions & ~bit;
    }
    showTaken(watched);
    return watched.taken == value->at.handle;
}

void HandheldWatcher::showTaken(Watched& watched) {
    const auto found = watched.taken ? watched.locos.find(*watched.taken) : watched.locos.end();
    const LocoValues values = found != watched.locos.end() ? found->second : LocoValues{};
    watched.handheld.speed = values.speed;
    watched.handheld.forward = values.forward;
    watched.handheld.functions = values.functions;
}

bool HandheldWatcher::tick(Clock::time_point now) {
    bool changed = false;
    for (auto& [node, watched] : watched_) {
        const auto silence = now - watched.lastHeard;
        HandheldState state = watched.handheld.state;
        if (silence > silentAfter_ + DroppedAfterSilence)
            state = HandheldState::Offline;
        else if (silence > silentAfter_ && state == HandheldState::Online)
            state = HandheldState::Silent;
        changed = changed || state != watched.handheld.state;
        watched.handheld.state = state;
    }
    return changed;
}

std::vector<Handheld> HandheldWatcher::handhelds() const {
    std::vector<Handheld> list;
    for (const auto& [node, watched] : watched_)
        list.push_back(watched.handheld);
    return list;
}

void HandheldWatcher::adopt(Handheld handheld, Clock::time_point now) {
    handheld.ours = false;
    handheld.loco.reset(); // its master decides now; the name it shows stays until it changes
    Watched& watched = watched_[handheld.slaveNode];
    watched.handheld = std::move(handheld);
    watched.lastHeard = now;
}

void HandheldWatcher::clear() {
    watched_.clear();
    roles_ = mcan::HandleRoles();
}

} // namespace stellwerk::mcanhandhelds
