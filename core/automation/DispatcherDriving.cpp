// The driving half of the Dispatcher: ways looked for and set, departures, braking, stops, the timers, and
// what stops a train or the whole automation.
#include "automation/Dispatcher.h"

#include <algorithm>
#include <cmath>

namespace stellwerk::automation {

namespace {

bool moving(TrainState state) {
    return state == TrainState::Running || state == TrainState::Braking;
}

bool due(Millis at, Millis now) {
    return at >= 0 && now >= at;
}

} // namespace

void Dispatcher::tick(Millis now) {
    if (paused_)
        return;
    for (auto& [locId, train] : trains_)
        if (train.mode == TrainMode::Automatic)
            if (const auto journey = journeys_.find(locId); journey != journeys_.end())
                driveTick(train, journey->second, now);
}

void Dispatcher::driveTick(Train& train, Journey& journey, Millis now) {
    switch (train.state) {
    case TrainState::Waiting:
        if (now >= journey.dwellUntil && now >= journey.nextTry)
            lookForWay(train, journey, now);
        return;
    case TrainState::SettingWay:
        if (journey.pending.empty() && due(journey.departAt, now))
            depart(train, journey, now);
        else if (!journey.pending.empty() && now >= journey.switchDeadline)
            turnoutsTimedOut(train, journey, now);
        return;
    case TrainState::Running:
    case TrainState::Braking:
        if (due(journey.stopAt, now))
            arrive(train, journey, now);
        else if (due(journey.brakeAt, now) && train.state == TrainState::Running)
            brake(train);
        else if (due(journey.lostAt, now))
            stopTrain(
                train, TrainState::Lost, AutomationEvent::Kind::Lost,
                train.name + " did not arrive in \"" +
                    blockName(journey.path.blocks[std::min(journey.next, journey.path.blocks.size() - 1)]) +
                    "\" in time: stopped, place it again");
        return;
    default:
        return;
    }
}

void Dispatcher::lookForWay(Train& train, Journey& journey, Millis now) {
    const TrainBody* body = tracking_.body(train.locId);
    const std::optional<Path> path =
        choice_.choose({body->frontBlock, body->towards}, train.lengthMm, stateFor(train.locId));
    if (!path || !reservations_.reserve(train.locId, *path)) {
        journey.nextTry = now + options_.retry;
        return;
    }
    journey = Journey{};
    journey.path = *path;
    train.destination = path->destination();
    std::string over;
    for (const int block : path->blocks)
        over += (over.empty() ? "\"" : ", \"") + blockName(block) + "\"";
    event(AutomationEvent::Kind::Reserved, train.locId, path->destination(),
          train.name + " reserved its way to \"" + blockName(path->destination()) + "\" over " + over);
    train.state = TrainState::SettingWay;
    journey.departAt = now;
    for (const auto& [article, position] : path->turnouts)
        if (!journey.pending.contains(article))
            sendSwitching(journey, article, position, now);
}

void Dispatcher::sendSwitching(Journey& journey, std::int64_t article, int position, Millis now) {
    journey.pending[article] = position;
    ++journey.attempts[article];
    journey.switchDeadline = now + options_.switchTimeout;
    command(DriveCommand::switching(article, position));
}

void Dispatcher::turnoutSwitched(std::int64_t article, int position, bool acknowledged, Millis now) {
    if (acknowledged)
        positions_[article] = position;
    for (auto& [locId, journey] : journeys_) {
        Train& train = trains_.at(locId);
        const auto pending = journey.pending.find(article);
        if (train.state != TrainState::SettingWay || pending == journey.pending.end() ||
            pending->second != position)
            continue;
        if (!acknowledged) {
            journey.switchDeadline = now; // the next tick retries or gives up
            continue;
        }
        journey.pending.erase(pending);
        journey.departAt = now + options_.settle;
        event(AutomationEvent::Kind::TurnoutSet, locId, 0,
              "turnout " + std::to_string(article) + " confirmed in position " + std::to_string(position) +
                  " for " + train.name);
    }
}

void Dispatcher::turnoutsTimedOut(Train& train, Journey& journey, Millis now) {
    const auto [article, position] = *journey.pending.begin();
    if (journey.attempts[article] < options_.switchAttempts) {
        for (const auto& [waiting, wanted] : std::map<std::int64_t, int>(journey.pending))
            sendSwitching(journey, waiting, wanted, now);
        return;
    }
    giveBackWay(train.locId);
    journey = Journey{};
    journey.dwellUntil = now + options_.dwell;
    stopTrain(train, TrainState::Fault, AutomationEvent::Kind::Fault,
              "turnout " + std::to_string(article) + " was not confirmed in position " +
                  std::to_string(position) + " after " + std::to_string(options_.switchAttempts) +
                  " attempts: " + train.name + " does not depart, its way is given back");
}

void Dispatcher::turnoutReported(std::int64_t article, int position, Millis /*now*/) {
    positions_[article] = position;
    const auto owner = reservations_.turnoutOwner(article);
    if (!owner || owner->second == position)
        return;
    Train& train = trains_.at(owner->first);
    const auto journey = journeys_.find(owner->first);
    if (journey != journeys_.end() && journey->second.pending.contains(article))
        return; // ours, not confirmed yet
    if (train.state == TrainState::Fault || train.state == TrainState::Lost)
        return;
    stopTrain(train, TrainState::Fault, AutomationEvent::Kind::Fault,
              "turnout " + std::to_string(article) + " was switched to position " + std::to_string(position) +
                  " on the way reserved for " + train.name + ": stopped");
}

void Dispatcher::depart(Train& train, Journey& journey, Millis now) {
    train.state = TrainState::Running;
    journey.lostAt = expectNextContact(train, journey, now);
    command(DriveCommand::speedOf(train.locId, options_.speeds.travel));
    event(AutomationEvent::Kind::Departed, train.locId, tracking_.body(train.locId)->frontBlock,
          train.name + " departed for \"" + blockName(journey.path.destination()) + "\"");
}

// The next contact the train must reach, at creep speed and half again, plus three seconds.
Millis Dispatcher::expectNextContact(const Train& train, const Journey& journey, Millis now) const {
    if (journey.next >= journey.path.blocks.size())
        return -1;
    const TrainBody* body = tracking_.body(train.locId);
    const int nextBlock = journey.path.blocks[journey.next];
    const trackgraph::Connection& way = graph_.connection(journey.path.connections[journey.next]);
    const trackgraph::End towards = trackgraph::otherEnd(way.to.end);
    const int firstContact =
        graph_.block(nextBlock).contacts.empty() ? 0 : tracking_.contactSpan(nextBlock, 0, towards).first;
    const int distance =
        std::max(0, graph_.block(body->frontBlock).lengthMm - body->frontMm) + way.lengthMm + firstContact;
    const double mmPerSecond = options_.speeds.mmPerSecond(options_.speeds.creep);
    return now + Millis(std::ceil(1500.0 * distance / mmPerSecond)) + 3000;
}

void Dispatcher::frontMoved(Train& train, Journey& journey, int block, int contactIndex, Millis now) {
    if (!moving(train.state))
        return;
    if (block != journey.path.destination()) {
        journey.lostAt = expectNextContact(train, journey, now);
        return;
    }
    journey.lostAt = -1;
    const std::size_t contacts = graph_.block(block).contacts.size();
    if (contacts >= 2) {
        if (std::size_t(contactIndex) + 1 == contacts)
            arrive(train, journey, now);
        else if (contactIndex == 0 && train.state == TrainState::Running)
            brake(train);
        return;
    }
    if (journey.stopAt < 0)
        approachStop(train, journey, block, now);
}

// A block with one contact: on to the stop point (the far end less the margin, the train inside the block)
// by the distance the speeds give.
void Dispatcher::approachStop(Train& train, Journey& journey, int block, Millis now) {
    const int length = graph_.block(block).lengthMm;
    const int target = length - std::min(options_.stopMarginMm, std::max(0, (length - train.lengthMm) / 2));
    const int remaining = target - tracking_.body(train.locId)->frontMm;
    const double travel = options_.speeds.mmPerSecond(options_.speeds.travel);
    const double creep = options_.speeds.mmPerSecond(options_.speeds.creep);
    if (remaining <= 0) {
        arrive(train, journey, now);
        return;
    }
    if (remaining <= options_.creepMm) {
        brake(train);
        journey.stopAt = now + Millis(1000.0 * remaining / creep);
        return;
    }
    journey.brakeAt = now + Millis(1000.0 * (remaining - options_.creepMm) / travel);
    journey.stopAt = journey.brakeAt + Millis(1000.0 * options_.creepMm / creep);
}

void Dispatcher::brake(Train& train) {
    train.state = TrainState::Braking;
    command(DriveCommand::speedOf(train.locId, options_.speeds.creep));
    event(AutomationEvent::Kind::Braking, train.locId, tracking_.body(train.locId)->frontBlock,
          train.name + " slows to creep speed");
}

void Dispatcher::arrive(Train& train, Journey& journey, Millis now) {
    const int block = tracking_.body(train.locId)->frontBlock;
    stopTrain(train, TrainState::Waiting, AutomationEvent::Kind::Stopped, train.name + " stopped");
    event(AutomationEvent::Kind::Arrived, train.locId, block,
          train.name + " arrived in \"" + blockName(block) + "\"");
    journey = Journey{};
    journey.dwellUntil = now + options_.dwell;
    train.destination.reset();
}

void Dispatcher::stopTrain(Train& train, TrainState state, AutomationEvent::Kind kind,
                           const std::string& why) {
    command(DriveCommand::speedOf(train.locId, 0));
    train.state = state;
    if (kind == AutomationEvent::Kind::Fault || kind == AutomationEvent::Kind::Lost ||
        kind == AutomationEvent::Kind::Overrun)
        ++faults_;
    const TrainBody* body = tracking_.body(train.locId);
    event(kind, train.locId, body ? body->frontBlock : 0, why);
}

// Everything the train holds ahead of the track it stands on.
void Dispatcher::giveBackWay(std::uint32_t locId) {
    std::vector<int> connections;
    if (const TrainBody* body = tracking_.body(locId))
        for (const BodySegment& segment : body->behind)
            if (!segment.isBlock)
                connections.push_back(segment.id);
    reservations_.releaseAllBut(locId, tracking_.blocksOf(locId), connections);
}

void Dispatcher::halt(const std::string& why) {
    paused_ = true;
    for (auto& [locId, train] : trains_) {
        if (train.mode != TrainMode::Automatic)
            continue;
        if (train.state == TrainState::Fault || train.state == TrainState::Lost)
            command(DriveCommand::speedOf(locId, 0));
        else
            stopTrain(train, TrainState::Stopped, AutomationEvent::Kind::Stopped,
                      train.name + " stopped: " + why);
    }
}

void Dispatcher::stationLost() {
    paused_ = true;
    for (auto& [locId, train] : trains_)
        if (train.mode == TrainMode::Automatic && train.state != TrainState::Fault &&
            train.state != TrainState::Lost)
            train.state = TrainState::Unknown;
    for (auto& [locId, journey] : journeys_)
        journey.pending.clear();
}

void Dispatcher::resume(Millis now) {
    paused_ = false;
    for (auto& [locId, train] : trains_) {
        if (train.mode != TrainMode::Automatic || train.state == TrainState::Lost)
            continue;
        if (train.state != TrainState::Waiting)
            command(DriveCommand::speedOf(locId, 0));
        giveBackWay(locId);
        train.state = TrainState::Waiting;
        train.destination.reset();
        journeys_[locId] = Journey{};
        journeys_[locId].dwellUntil = now;
    }
}

void Dispatcher::finish() {
    paused_ = true;
    for (auto& [locId, train] : trains_) {
        if (train.mode != TrainMode::Automatic)
            continue;
        if (moving(train.state))
            stopTrain(train, TrainState::Stopped, AutomationEvent::Kind::Stopped,
                      train.name + " stopped: the run ends");
        else
            command(DriveCommand::speedOf(locId, 0));
        if (train.state == TrainState::SettingWay || train.state == TrainState::Waiting)
            train.state = TrainState::Stopped;
        giveBackWay(locId);
        journeys_.erase(locId);
    }
}

} // namespace stellwerk::automation
