#include "automation/Dispatcher.h"

#include <algorithm>

namespace stellwerk::automation {

using trackgraph::End;

std::string_view trainStateName(TrainState state) {
    switch (state) {
    case TrainState::Waiting:
        return "waiting";
    case TrainState::SettingWay:
        return "setting-way";
    case TrainState::Running:
        return "running";
    case TrainState::Braking:
        return "braking";
    case TrainState::Stopped:
        return "stopped";
    case TrainState::Unknown:
        return "stopped-unknown";
    case TrainState::Fault:
        return "fault";
    case TrainState::Lost:
        return "lost";
    }
    return "?";
}

std::string_view eventKindName(AutomationEvent::Kind kind) {
    static constexpr std::string_view names[] = {
        "placed",   "reserved", "turnout-set", "departed", "entered", "braking", "stopped",   "arrived",
        "released", "ghost",    "lost",        "overrun",  "fault",   "manual",  "automatic", "reversed"};
    return names[std::size_t(kind)];
}

Dispatcher::Dispatcher(const trackgraph::TrackGraph& graph, Options options)
    : graph_(graph), options_(options), tracking_(graph), reservations_(graph), choice_(graph) {}

std::optional<std::string> Dispatcher::place(std::uint32_t locId, const std::string& name, int lengthMm,
                                             std::int64_t contact, End towards) {
    int block = 0;
    for (const trackgraph::Block& candidate : graph_.blocks())
        for (const trackgraph::ContactOnBlock& on : candidate.contacts)
            if (on.contact.number == contact && block == 0)
                block = candidate.id;
    if (block == 0)
        return name + ": no block of the track plan holds contact " + std::to_string(contact);
    return placeInBlock(locId, name, lengthMm, block, towards);
}

std::optional<std::string> Dispatcher::placeInBlock(std::uint32_t locId, const std::string& name,
                                                    int lengthMm, int block, End towards) {
    if (block <= 0 || block > int(graph_.blocks().size()))
        return name + ": the track plan has no block " + std::to_string(block);
    if (const std::uint32_t other = tracking_.trainIn(block); other != 0 && other != locId)
        return name + ": block \"" + blockName(block) + "\" holds " + trains_.at(other).name + " already";
    if (const std::uint32_t owner = reservations_.blockOwner(block); owner != 0 && owner != locId)
        return name + ": block \"" + blockName(block) + "\" is reserved for " + trains_.at(owner).name;
    if (tracking_.body(locId) && tracking_.body(locId)->frontBlock != block) // moved by hand elsewhere
        reservations_.releaseAllBut(locId, {}, {});
    giveBackWay(locId);
    journeys_.erase(locId); // its way led from where it stood; it stands until resumed
    tracking_.place(locId, block, towards, lengthMm);
    reservations_.holdBlock(locId, block);
    Train& train = trains_[locId];
    train = Train{locId,        name,           lengthMm,      train.mode, TrainState::Stopped,
                  std::nullopt, train.schedule, train.pushPull};
    event(AutomationEvent::Kind::Placed, locId, block,
          name + " placed in \"" + blockName(block) + "\" facing end " +
              std::string(trackgraph::endName(towards)));
    return std::nullopt;
}

bool Dispatcher::remove(std::uint32_t locId) {
    const auto found = trains_.find(locId);
    if (found == trains_.end())
        return false;
    const int block = tracking_.body(locId)->frontBlock;
    const std::string name = found->second.name;
    if (found->second.mode == TrainMode::Automatic)
        command(DriveCommand::speedOf(locId, 0));
    reservations_.releaseAllBut(locId, {}, {});
    tracking_.remove(locId);
    journeys_.erase(locId);
    mustBeSeen_.erase(locId);
    stopAtStop_.erase(locId);
    signalsToStop(locId);
    trains_.erase(found);
    event(AutomationEvent::Kind::Released, locId, block,
          name + " taken off \"" + blockName(block) + "\": no longer tracked");
    return true;
}

void Dispatcher::setMode(std::uint32_t locId, TrainMode mode, Millis now) {
    const auto found = trains_.find(locId);
    if (found == trains_.end())
        return;
    Train& train = found->second;
    train.mode = mode;
    journeys_.erase(locId);
    stopAtStop_.erase(locId);
    if (mode == TrainMode::Automatic && train.state != TrainState::Lost) {
        train.state = TrainState::Waiting;
        journeys_[locId].dwellUntil = now;
        command(DriveCommand::speedOf(locId, 0)); // it stands until its way is set
    }
}

std::optional<std::string> Dispatcher::setSchedule(std::uint32_t locId, Schedule schedule) {
    const auto found = trains_.find(locId);
    if (found == trains_.end())
        return "0x" + std::to_string(locId) + " has a schedule but is not placed";
    if (schedule.stops.empty()) {
        found->second.pushPull = schedule.pushPull;
        found->second.schedule.reset();
        return std::nullopt;
    }
    for (ScheduleStop& stop : schedule.stops) {
        const auto block = std::find_if(graph_.blocks().begin(), graph_.blocks().end(),
                                        [&](const trackgraph::Block& b) { return b.name == stop.block; });
        if (block == graph_.blocks().end())
            return found->second.name + ": no block of the track plan is named \"" + stop.block + "\"";
        stop.blockId = block->id;
    }
    found->second.pushPull = schedule.pushPull;
    found->second.schedule = std::move(schedule);
    return std::nullopt;
}

void Dispatcher::setPushPull(std::uint32_t locId, bool pushPull) {
    if (const auto found = trains_.find(locId); found != trains_.end())
        found->second.pushPull = pushPull;
}

void Dispatcher::takenByHand(std::uint32_t locId, const std::string& by) {
    const auto found = trains_.find(locId);
    if (found == trains_.end() || found->second.mode != TrainMode::Automatic)
        return;
    Train& train = found->second;
    train.mode = TrainMode::Manual;
    train.state = TrainState::Stopped;
    journeys_.erase(locId);
    stopAtStop_.erase(locId); // a signal it was given stays until it has passed it (entered())
    event(AutomationEvent::Kind::Manual, locId, tracking_.body(locId)->frontBlock,
          train.name + " is driven by " + by + ": automation leaves it, its blocks stay reserved");
}

void Dispatcher::handBack(std::uint32_t locId, Millis now) {
    const auto found = trains_.find(locId);
    if (found == trains_.end() || found->second.mode != TrainMode::Manual)
        return;
    giveBackWay(locId);
    found->second.destination.reset();
    setMode(locId, TrainMode::Automatic, now);
    const int block = tracking_.body(locId)->frontBlock;
    event(AutomationEvent::Kind::Automatic, locId, block,
          found->second.name + " is driven by the automation again, from \"" + blockName(block) + "\"");
}

const Train* Dispatcher::train(std::uint32_t locId) const {
    const auto found = trains_.find(locId);
    return found == trains_.end() ? nullptr : &found->second;
}

void Dispatcher::occupancyRead(const std::set<trackgraph::ContactKey>& occupied) {
    for (const int block : tracking_.reread(occupied))
        event(AutomationEvent::Kind::Ghost, 0, block,
              "an unknown occupant in \"" + blockName(block) + "\": no train can have reached it");
    // A train seen in its block when the station fell silent must be seen there now; one that was not
    // (past the block's only contact) is taken to be where it was: had it run on, the next block would show
    // an unknown occupant.
    for (auto& [locId, train] : trains_)
        if (train.state == TrainState::Unknown && mustBeSeen_.contains(locId) &&
            !tracking_.blockOccupied(tracking_.body(locId)->frontBlock))
            stopTrain(train, TrainState::Lost, AutomationEvent::Kind::Lost,
                      StopReason::noLongerSeen(train.name));
    mustBeSeen_.clear();
}

void Dispatcher::contactChanged(const trackgraph::ContactKey& contact, bool occupied, Millis now) {
    if (occupied) {
        sighted(tracking_.occupied(contact, [this](std::uint32_t locId) { return expectedNext(locId); }),
                now);
        return;
    }
    tracking_.freed(contact);
    for (const auto& [locId, train] : trains_)
        releaseBehind(locId);
}

// Where the train goes next: along its reserved way, or, for a manual train, where the turnouts lead.
std::optional<NextBlock> Dispatcher::expectedNext(std::uint32_t locId) const {
    const Train& train = trains_.at(locId);
    if (train.mode == TrainMode::Manual)
        return followedNext(locId);
    const auto journey = journeys_.find(locId);
    if (journey == journeys_.end() || journey->second.next >= journey->second.path.blocks.size())
        return std::nullopt;
    const Journey& on = journey->second;
    return NextBlock{on.path.connections[on.next], on.path.blocks[on.next]};
}

std::optional<NextBlock> Dispatcher::followedNext(std::uint32_t locId) const {
    const TrainBody* body = tracking_.body(locId);
    const trackgraph::BlockEnd front{body->frontBlock, body->towards};
    const trackgraph::Lead lead = graph_.follow(front, [this](std::int64_t article) -> std::optional<int> {
        const auto found = positions_.find(article);
        return found == positions_.end() ? std::nullopt : std::optional<int>(found->second);
    });
    if (lead.kind != trackgraph::LeadKind::Block)
        return std::nullopt;
    for (const int id : graph_.connectionsFrom(front))
        if (graph_.connection(id).to == lead.reached)
            return NextBlock{id, lead.reached.block};
    return std::nullopt;
}

void Dispatcher::sighted(const Sighting& sighting, Millis now) {
    switch (sighting.kind) {
    case Sighting::Kind::None:
        return;
    case Sighting::Kind::Moved: {
        Train& train = trains_.at(sighting.locId);
        if (const auto journey = journeys_.find(sighting.locId); journey != journeys_.end())
            frontMoved(train, journey->second, sighting.block, sighting.contactIndex, now);
        return;
    }
    case Sighting::Kind::Entered:
        entered(sighting, now);
        return;
    case Sighting::Kind::Ghost:
        ghostSeen(sighting.block);
        return;
    }
}

void Dispatcher::entered(const Sighting& sighting, Millis now) {
    Train& train = trains_.at(sighting.locId);
    ++blockMoves_;
    event(AutomationEvent::Kind::Entered, train.locId, sighting.block,
          train.name + " entered \"" + blockName(sighting.block) + "\"");
    signalsToStop(train.locId); // the signal it passed is behind it
    const std::uint32_t owner = reservations_.blockOwner(sighting.block);
    if (owner != 0 && owner != train.locId && trains_.at(owner).mode == TrainMode::Automatic)
        stopTrain(
            trains_.at(owner), TrainState::Fault, AutomationEvent::Kind::Fault,
            StopReason::otherEnteredItsWay(trains_.at(owner).name, train.name, blockName(sighting.block)));
    if (owner == 0)
        reservations_.holdBlock(train.locId, sighting.block);
    if (const auto journey = journeys_.find(train.locId); journey != journeys_.end()) {
        ++journey->second.next;
        frontMoved(train, journey->second, sighting.block, sighting.contactIndex, now);
    }
    releaseBehind(train.locId);
}

void Dispatcher::ghostSeen(int block) {
    if (const std::optional<std::uint32_t> driver = overrunBy(block)) {
        command(DriveCommand::powerOff());
        Train& train = trains_.at(*driver);
        stopTrain(train, TrainState::Fault, AutomationEvent::Kind::Overrun,
                  StopReason::ranIntoUnreserved(train.name, blockName(block)));
        halt("overrun");
        return;
    }
    event(AutomationEvent::Kind::Ghost, 0, block,
          "an unknown occupant in \"" + blockName(block) + "\": no train can have reached it");
    const std::uint32_t owner = reservations_.blockOwner(block);
    if (owner != 0 && trains_.at(owner).mode == TrainMode::Automatic &&
        trains_.at(owner).state != TrainState::Fault)
        stopTrain(trains_.at(owner), TrainState::Fault, AutomationEvent::Kind::Fault,
                  StopReason::unknownOccupantAhead(trains_.at(owner).name, blockName(block)));
}

// The automatic train whose front end leads into the block, which is not reserved for it: whether it runs or
// stands, an occupant appearing right ahead of it is taken for the train running on.
std::optional<std::uint32_t> Dispatcher::overrunBy(int block) const {
    for (const auto& [locId, train] : trains_) {
        if (train.mode != TrainMode::Automatic || reservations_.blockOwner(block) == locId ||
            train.state == TrainState::Lost || train.state == TrainState::Unknown)
            continue;
        const TrainBody* body = tracking_.body(locId);
        for (const int id : graph_.connectionsFrom({body->frontBlock, body->towards}))
            if (graph_.connection(id).to.block == block)
                return locId;
    }
    return std::nullopt;
}

void Dispatcher::releaseBehind(std::uint32_t locId) {
    for (const BodySegment& segment : tracking_.left(locId)) {
        if (!segment.isBlock) {
            reservations_.releaseConnection(locId, segment.id);
            continue;
        }
        if (reservations_.blockOwner(segment.id) != locId)
            continue;
        reservations_.releaseBlock(locId, segment.id);
        event(AutomationEvent::Kind::Released, locId, segment.id,
              trains_.at(locId).name + " left \"" + blockName(segment.id) + "\"");
    }
}

TrackState Dispatcher::stateFor(std::uint32_t locId) const {
    TrackState state;
    state.blockFree = [this, locId](int block) {
        const std::uint32_t in = tracking_.trainIn(block);
        return reservations_.blockAvailable(block, locId) && !tracking_.isGhost(block) &&
               (in == 0 || in == locId) && (in == locId || !tracking_.blockOccupied(block));
    };
    state.connectionFree = [this, locId](int id) { return reservations_.connectionAvailable(id, locId); };
    state.trainFacing = [this, locId](int block) -> std::optional<End> {
        const std::uint32_t in = tracking_.trainIn(block);
        if (in == 0 || in == locId)
            return std::nullopt;
        return tracking_.body(in)->towards;
    };
    state.travelling = [this, locId](int block) -> std::optional<End> {
        for (const auto& [other, body] : trains_) {
            if (other == locId)
                continue;
            if (tracking_.body(other)->frontBlock == block)
                return tracking_.body(other)->towards;
            const auto journey = journeys_.find(other);
            if (journey == journeys_.end())
                continue;
            const Path& path = journey->second.path;
            for (std::size_t i = journey->second.next; i < path.blocks.size(); ++i)
                if (path.blocks[i] == block)
                    return trackgraph::otherEnd(graph_.connection(path.connections[i]).to.end);
        }
        return std::nullopt;
    };
    return state;
}

std::vector<DriveCommand> Dispatcher::takeCommands() {
    return std::exchange(commands_, {});
}

std::vector<AutomationEvent> Dispatcher::takeEvents() {
    return std::exchange(events_, {});
}

void Dispatcher::event(AutomationEvent::Kind kind, std::uint32_t locId, int block, std::string text,
                       StopReason reason) {
    events_.push_back({kind, locId, block, std::move(text), std::move(reason)});
}

std::string Dispatcher::blockName(int block) const {
    return block > 0 && block <= int(graph_.blocks().size()) ? graph_.block(block).name : std::string("?");
}

} // namespace stellwerk::automation
