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
        if (now + (journey.dwellFrom >= 0 ? options_.prepare : 0) >= journey.dwellUntil &&
            now >= journey.nextTry)
            lookForWay(train, journey, now);
        return;
    case TrainState::SettingWay:
        if (journey.pending.empty() && due(journey.departAt, now) && now >= journey.dwellUntil)
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
                StopReason::didNotArrive(
                    train.name,
                    blockName(journey.path.blocks[std::min(journey.next, journey.path.blocks.size() - 1)])));
        return;
    default:
        return;
    }
}

void Dispatcher::lookForWay(Train& train, Journey& journey, Millis now) {
    const std::optional<Way> way = wayFor(train, journey, now);
    if (train.state != TrainState::Waiting)
        return;
    if (!way || !reservations_.reserve(train.locId, way->path)) {
        journey.nextTry = now + options_.retry;
        return;
    }
    if (way->turn)
        turn(train);
    const Path* path = &way->path;
    const Journey dwelling = journey;
    journey = Journey{};
    journey.dwellUntil = dwelling.dwellUntil;
    journey.dwellFrom = dwelling.dwellFrom;
    journey.wayInTime = now <= dwelling.dwellUntil;
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

// The way to the schedule's next stop, or to any block the train may stop in; turned round when it may
// and finds none forwards. A train at the end of its schedule stops for good; one already in its next
// stop's block stands its dwell there.
std::optional<Dispatcher::Way> Dispatcher::wayFor(Train& train, Journey& journey, Millis now) {
    const TrainBody* body = tracking_.body(train.locId);
    const trackgraph::BlockEnd front{body->frontBlock, body->towards};
    if (train.schedule && train.schedule->done()) {
        stopTrain(train, TrainState::Stopped, AutomationEvent::Kind::Stopped,
                  train.name + " has run its schedule: it stays in \"" + blockName(body->frontBlock) + "\"");
        return std::nullopt;
    }
    if (train.schedule && train.schedule->stops[train.schedule->next].blockId == body->frontBlock &&
        journey.dwellFrom < 0) {
        reachedStop(train, journey, body->frontBlock, now);
        return std::nullopt;
    }
    if (std::optional<Path> ahead = wayFrom(train, front))
        return Way{std::move(*ahead), false};
    if (!mayTurn(train, front) || !body->behind.empty())
        return std::nullopt;
    if (std::optional<Path> back = wayFrom(train, {front.block, trackgraph::otherEnd(front.end)}))
        return Way{std::move(*back), true};
    return std::nullopt;
}

std::optional<Path> Dispatcher::wayFrom(const Train& train, const trackgraph::BlockEnd& front) const {
    if (!train.schedule)
        return choice_.choose(front, train.lengthMm, stateFor(train.locId));
    return choice_.chooseTo(front, train.schedule->stops[train.schedule->next].blockId, train.lengthMm,
                            stateFor(train.locId));
}

// A push-pull train anywhere; a train with a schedule at a terminus: no way leads from the end it faces to
// another block, whatever the turnouts (the track ends at buffer stops). A train without a schedule stays
// at a terminus: it would only turn to stand in the way of others in the station's throat.
bool Dispatcher::mayTurn(const Train& train, const trackgraph::BlockEnd& front) const {
    return train.pushPull || (train.schedule && graph_.connectionsFrom(front).empty());
}

void Dispatcher::turn(Train& train) {
    if (!tracking_.reverse(train.locId))
        return;
    command(DriveCommand::reverse(train.locId));
    const TrainBody* body = tracking_.body(train.locId);
    event(AutomationEvent::Kind::Reversed, train.locId, body->frontBlock,
          train.name + " changes direction in \"" + blockName(body->frontBlock) + "\": it faces end " +
              std::string(trackgraph::endName(body->towards)) + " now");
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
              StopReason::turnoutNotConfirmed(train.name, article, position, options_.switchAttempts));
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
    if (train.mode != TrainMode::Automatic || train.state == TrainState::Fault ||
        train.state == TrainState::Lost)
        return;
    stopTrain(train, TrainState::Fault, AutomationEvent::Kind::Fault,
              StopReason::turnoutSwitchedUnder(train.name, article, position));
}

void Dispatcher::depart(Train& train, Journey& journey, Millis now) {
    if (journey.dwellFrom >= 0 && journey.wayInTime)
        worstDwellError_ = std::max(worstDwellError_, now - journey.dwellUntil);
    train.state = TrainState::Running;
    journey.lostAt = expectNextContact(train, journey, now);
    clearSignals(train);
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
    journey.stopFrontMm = target;
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
    tracking_.advanced(train.locId, journey.stopFrontMm);
    releaseBehind(train.locId);
    stopTrain(train, TrainState::Waiting, AutomationEvent::Kind::Stopped, train.name + " stopped");
    journey = Journey{};
    train.destination.reset();
    if (stopAtStop_.erase(train.locId) > 0) {
        if (train.schedule && !train.schedule->done() &&
            train.schedule->stops[train.schedule->next].blockId == block)
            train.schedule->advance();
        return holdAtStop(train, block);
    }
    if (train.schedule && !train.schedule->done() &&
        train.schedule->stops[train.schedule->next].blockId == block)
        return reachedStop(train, journey, block, now);
    event(AutomationEvent::Kind::Arrived, train.locId, block,
          train.name + " arrived in \"" + blockName(block) + "\"");
    // On its way to a schedule's stop it goes on as soon as the way is free.
    journey.dwellUntil = now + (train.schedule ? 0 : options_.dwell);
}

// At the schedule's next stop: it stands there for the stop's dwell, and the schedule moves on.
void Dispatcher::reachedStop(Train& train, Journey& journey, int block, Millis now) {
    Schedule& schedule = *train.schedule;
    const ScheduleStop& stop = schedule.stops[schedule.next];
    journey.dwellFrom = now;
    journey.dwellUntil = now + stop.dwellMs;
    event(AutomationEvent::Kind::Arrived, train.locId, block,
          train.name + " arrived in \"" + blockName(block) + "\", stop " + std::to_string(schedule.next + 1) +
              " of " + std::to_string(schedule.stops.size()) + ", for " +
              std::to_string(stop.dwellMs / 1000) + " s");
    schedule.advance();
}

// Asked to stop at its next stop: it stays where it arrived, manual, holding its block.
void Dispatcher::holdAtStop(Train& train, int block) {
    giveBackWay(train.locId);
    train.mode = TrainMode::Manual;
    train.state = TrainState::Stopped;
    event(AutomationEvent::Kind::Arrived, train.locId, block,
          train.name + " arrived in \"" + blockName(block) + "\" and stays there: start it again to go on");
}

void Dispatcher::stopAtNextStop(Millis /*now*/) {
    std::vector<std::uint32_t> standing;
    for (auto& [locId, train] : trains_) {
        if (train.mode != TrainMode::Automatic)
            continue;
        if (moving(train.state) && !paused_)
            stopAtStop_.insert(locId);
        else
            standing.push_back(locId);
    }
    for (const std::uint32_t locId : standing) {
        Train& train = trains_.at(locId);
        if (train.state == TrainState::SettingWay || train.state == TrainState::Waiting)
            command(DriveCommand::speedOf(locId, 0));
        journeys_.erase(locId);
        train.destination.reset();
        holdAtStop(train, tracking_.body(locId)->frontBlock);
    }
}

void Dispatcher::stopTrain(Train& train, TrainState state, AutomationEvent::Kind kind, StopReason reason) {
    const std::string why = describe(reason);
    stopTrain(train, state, kind, why);
    events_.back().reason = std::move(reason);
}

void Dispatcher::stopTrain(Train& train, TrainState state, AutomationEvent::Kind kind,
                           const std::string& why) {
    signalsToStop(train.locId);
    command(DriveCommand::speedOf(train.locId, 0));
    train.state = state;
    if (kind == AutomationEvent::Kind::Fault || kind == AutomationEvent::Kind::Lost ||
        kind == AutomationEvent::Kind::Overrun)
        ++faults_;
    const TrainBody* body = tracking_.body(train.locId);
    event(kind, train.locId, body ? body->frontBlock : 0, why);
}

void Dispatcher::clearSignals(const Train& train) {
    const TrainBody* body = tracking_.body(train.locId);
    if (!body)
        return;
    for (const trackgraph::SignalOnTrack& signal : graph_.block(body->frontBlock).signalsAlong)
        if (signal.article && signal.towards == body->towards) {
            command(DriveCommand::switching(*signal.article, options_.signalProceed));
            cleared_[train.locId].push_back(*signal.article);
        }
}

void Dispatcher::signalsToStop(std::uint32_t locId) {
    const auto cleared = cleared_.find(locId);
    if (cleared == cleared_.end())
        return;
    for (const std::int64_t article : cleared->second)
        command(DriveCommand::switching(article, options_.signalStop));
    cleared_.erase(cleared);
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
    for (auto& [locId, train] : trains_) {
        if (train.mode != TrainMode::Automatic || train.state == TrainState::Fault ||
            train.state == TrainState::Lost || train.state == TrainState::Unknown)
            continue;
        if (tracking_.blockOccupied(tracking_.body(locId)->frontBlock))
            mustBeSeen_.insert(locId);
        train.state = TrainState::Unknown;
        event(AutomationEvent::Kind::Stopped, locId, tracking_.body(locId)->frontBlock,
              train.name + " is stopped-unknown: the station does not answer, automation is paused");
    }
    for (auto& [locId, journey] : journeys_)
        journey.pending.clear();
}

void Dispatcher::stationBack() {
    for (auto& [locId, train] : trains_) {
        if (train.mode != TrainMode::Automatic || train.state != TrainState::Unknown)
            continue;
        command(DriveCommand::speedOf(locId, 0));
        event(AutomationEvent::Kind::Stopped, locId, tracking_.body(locId)->frontBlock,
              train.name +
                  " is told to stop: the station answers again; it stays until automation is resumed");
    }
}

void Dispatcher::resume(Millis now) {
    paused_ = false;
    for (auto& [locId, train] : trains_) {
        if (train.mode != TrainMode::Automatic || train.state == TrainState::Lost)
            continue;
        if (stopAtStop_.erase(locId) > 0) { // asked to stop at its stop, and stopped before it: it stays
            journeys_.erase(locId);
            holdAtStop(train, tracking_.body(locId)->frontBlock);
            continue;
        }
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
