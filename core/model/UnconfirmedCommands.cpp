#include "model/UnconfirmedCommands.h"

#include <algorithm>

namespace stellwerk::model {
namespace {

bool contains(const std::vector<int>& values, int value) {
    return std::find(values.begin(), values.end(), value) != values.end();
}

bool sameLocomotive(const CommandTarget& a, const CommandTarget& b) {
    return a.isLocomotive() && b.isLocomotive() && a.id == b.id;
}

} // namespace

std::optional<int> UnconfirmedCommands::restoreFor(CommandTarget target, std::optional<int> confirmed) {
    if (confirmed)
        return confirmed;
    if (target.kind == CommandTarget::Kind::Speed || target.kind == CommandTarget::Kind::Power)
        return 0; // nothing confirmed: standing, and off
    return std::nullopt;
}

// Whether a late copy of a failed command must be undone: never when undoing would make a train faster,
// start one or switch the power on.
bool UnconfirmedCommands::mustUndo(CommandTarget target, int failedValue, int restore) {
    switch (target.kind) {
    case CommandTarget::Kind::Speed:
        return failedValue > restore;
    case CommandTarget::Kind::Power:
        return failedValue != 0 && restore == 0;
    default:
        return failedValue != restore;
    }
}

// In the "stop" aftermath every command to a locomotive is answered by stopping it.
std::optional<int> UnconfirmedCommands::stopValueFor(CommandTarget target) const {
    if (aftermath_ == Aftermath::StopLocomotives && target.isLocomotive())
        return 0;
    return std::nullopt;
}

void UnconfirmedCommands::failed(CommandTarget target, int value, std::optional<int> confirmed) {
    auto [it, added] = entries_.try_emplace(target);
    Entry& entry = it->second;
    if (added)
        entry.restore = restoreFor(target, confirmed);
    if (!contains(entry.failedValues, value))
        entry.failedValues.push_back(value);
    entry.phase = Phase::Waiting;
}

void UnconfirmedCommands::acknowledged(CommandTarget target, int value, Clock::time_point now) {
    const auto watch = [&](Entry& entry) {
        entry.phase = Phase::Watching;
        entry.until = now + WatchTime;
    };
    if (const auto it = entries_.find(target); it != entries_.end()) {
        it->second.restore = value;
        std::erase(it->second.failedValues, value);
        watch(it->second);
    }
    // Stopping a locomotive brings back every one of its targets in the "stop" aftermath.
    if (target.kind == CommandTarget::Kind::Speed && value == 0 && stopValueFor(target))
        for (auto& [other, entry] : entries_)
            if (sameLocomotive(other, target) && entry.phase == Phase::Correcting)
                watch(entry);
}

std::optional<Correction> UnconfirmedCommands::reported(CommandTarget target, int value,
                                                        Clock::time_point now) {
    const auto it = entries_.find(target);
    if (it == entries_.end())
        return std::nullopt;
    Entry& entry = it->second;
    const auto watch = [&] {
        entry.phase = Phase::Watching;
        entry.until = now + WatchTime;
    };
    if (!contains(entry.failedValues, value)) {
        entry.restore = value; // someone else's change, or nothing happened: that is what the layout has
        if (entry.phase == Phase::Waiting || entry.phase == Phase::Querying)
            watch();
        return std::nullopt;
    }
    if (entry.phase == Phase::Correcting)
        return std::nullopt; // being brought back already
    if (stopValueFor(target) && !(target.kind == CommandTarget::Kind::Speed && value == 0)) {
        entry.phase = Phase::Correcting;
        return Correction{CommandTarget::speed(std::uint32_t(target.id)), value, 0, true};
    }
    if (entry.restore && mustUndo(target, value, *entry.restore)) {
        entry.phase = Phase::Correcting;
        return Correction{target, value, entry.restore, true};
    }
    // A late stop (or anything that needs no undoing) stays: it is what the layout has now.
    entry.restore = value;
    std::erase(entry.failedValues, value);
    watch();
    return Correction{target, value, std::nullopt, true};
}

std::optional<int> UnconfirmedCommands::correctionFor(CommandTarget target, const Entry& entry) const {
    if (!entry.restore)
        return std::nullopt;
    for (const int value : entry.failedValues)
        if (mustUndo(target, value, *entry.restore))
            return value;
    return std::nullopt;
}

Recovery UnconfirmedCommands::heardAgain(Clock::time_point now) {
    Recovery recovery;
    for (auto& [target, entry] : entries_) {
        if (entry.phase != Phase::Waiting)
            continue;
        if (stopValueFor(target)) {
            const CommandTarget speed = CommandTarget::speed(std::uint32_t(target.id));
            auto& corrections = recovery.corrections;
            if (std::none_of(corrections.begin(), corrections.end(),
                             [&](const Correction& c) { return c.target == speed; }))
                corrections.push_back({speed, entry.failedValues.back(), 0, false});
            entry.phase = Phase::Correcting;
        } else if (target.isLocomotive()) {
            recovery.queries.push_back(target); // the station says what it has: then it is clear
            entry.phase = Phase::Querying;
        } else if (const auto failedValue = correctionFor(target, entry)) {
            recovery.corrections.push_back({target, *failedValue, entry.restore, false});
            entry.phase = Phase::Correcting;
        } else {
            entry.phase = Phase::Watching;
            entry.until = now + WatchTime;
        }
    }
    return recovery;
}

void UnconfirmedCommands::queryUnanswered(CommandTarget target) {
    const auto it = entries_.find(target);
    if (it != entries_.end() && it->second.phase == Phase::Querying)
        it->second.phase = Phase::Waiting;
}

std::optional<int> UnconfirmedCommands::restoreValue(CommandTarget target) const {
    const auto it = entries_.find(target);
    return it == entries_.end() ? std::nullopt : it->second.restore;
}

std::vector<CommandTarget> UnconfirmedCommands::targets() const {
    std::vector<CommandTarget> targets;
    targets.reserve(entries_.size());
    for (const auto& [target, entry] : entries_)
        targets.push_back(target);
    return targets;
}

void UnconfirmedCommands::settle(Clock::time_point now) {
    std::erase_if(entries_, [now](const auto& item) {
        return item.second.phase == Phase::Watching && item.second.until <= now;
    });
}

} // namespace stellwerk::model
