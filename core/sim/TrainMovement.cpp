#include "sim/TrainMovement.h"

#include "cs2/Codec.h"
#include "cs2/LocIdText.h"
#include "cs2/Request.h"
#include "sim/SimulatedStation.h"

#include <algorithm>
#include <cmath>

namespace stellwerk::sim {

using trackgraph::ContactKey;

namespace {

constexpr std::uint8_t Backward = 2;                  // SimulatedLoco::direction, document 3.5
constexpr std::chrono::milliseconds LongestStep{100}; // trains never pass through each other
constexpr std::chrono::milliseconds NoTime{0};

trackgraph::TrackGraph graphOf(const SimulatedStation& station) {
    const StationLayout& layout = station.layout();
    return trackgraph::TrackGraph::derive(layout.trackPlan(), &layout.accessories(), &layout.routes());
}

// The block holding a contact of this number (of any feedback device), and the contact there.
std::optional<std::pair<int, trackgraph::ContactOnBlock>> contactNumbered(const trackgraph::TrackGraph& graph,
                                                                          std::int64_t number) {
    for (const trackgraph::Block& block : graph.blocks())
        for (const trackgraph::ContactOnBlock& contact : block.contacts)
            if (contact.contact.number == number)
                return std::pair{block.id, contact};
    return std::nullopt;
}

} // namespace

TrainMovement::TrainMovement(SimulatedStation& station, std::vector<TrainPlacement> placements,
                             Options options, QObject* parent)
    : QObject(parent), station_(station), options_(options), graph_(graphOf(station)),
      turnouts_(station, graph_), watch_(graph_), placements_(std::move(placements)) {
    timer_.setInterval(options_.tick);
    connect(&timer_, &QTimer::timeout, this, [this] { advance(options_.tick); });
}

TrainMovement::TrainMovement(SimulatedStation& station, std::vector<TrainPlacement> placements,
                             QObject* parent)
    : TrainMovement(station, std::move(placements), Options{}, parent) {}

TrainMovement::~TrainMovement() = default;

void TrainMovement::start() {
    if (!placed_) {
        for (const TrainPlacement& placement : placements_)
            if (const std::optional<std::string> problem = place(placement))
                problems_.push_back(*problem);
        placed_ = true;
    }
    updateLoad();
    timer_.start();
}

void TrainMovement::stop() {
    timer_.stop();
}

std::optional<std::string> TrainMovement::place(const TrainPlacement& placement) {
    const auto found = contactNumbered(graph_, placement.contact);
    if (!found)
        return cs2::locomotiveText(cs2::LocId(placement.locId)) +
               ": no block of the track plan holds contact " + std::to_string(placement.contact);
    remove(placement.locId);
    trains_.push_back({placement.locId,
                       nameOf(placement.locId),
                       TrainRun::placed(graph_, found->second, found->first, placement.towards,
                                        options_.trainLengthMm, turnouts_.positionOf()),
                       true,
                       false,
                       {}});
    updateContacts(trains_.back());
    return std::nullopt;
}

// Takes a locomotive's train off the track, freeing its contacts.
void TrainMovement::remove(std::uint32_t locId) {
    const auto found = std::ranges::find(trains_, locId, &Train::locId);
    if (found == trains_.end())
        return;
    const std::set<ContactKey> left = std::move(found->contacts);
    trains_.erase(found);
    for (const ContactKey& contact : left)
        release(contact);
}

void TrainMovement::advance(std::chrono::milliseconds elapsed) {
    for (auto remaining = elapsed; remaining > NoTime; remaining -= LongestStep)
        step(std::min(remaining, LongestStep));
    updateLoad();
}

void TrainMovement::step(std::chrono::milliseconds elapsed) {
    turnouts_.update(elapsed);
    if (station_.power() != SimulatedStation::Power::Running)
        return;
    for (Train& train : trains_)
        move(train, elapsed);
    watchTrains();
}

void TrainMovement::move(Train& train, std::chrono::milliseconds elapsed) {
    const SimulatedLoco* loco = station_.loco(train.locId);
    if (!loco || train.derailed)
        return;
    const bool ahead = loco->direction != Backward; // placed running forward
    if (ahead != train.headingAhead) {
        train.run.turnAround(graph_);
        train.headingAhead = ahead;
    }
    if (loco->speed == 0)
        return;
    const double distanceMm =
        loco->speed / 1000.0 * options_.topSpeedMmPerSecond * double(elapsed.count()) / 1000.0;
    const std::optional<RunStop> stop = train.run.advance(distanceMm, graph_, turnouts_.positionOf());
    updateContacts(train);
    if (stop)
        if (const std::optional<Accident> accident = watch_.ranInto(onTrack(train), *stop))
            report(*accident);
}

// Trains touching each other, and turnouts moving under trains.
void TrainMovement::watchTrains() {
    std::vector<TrainOnTrack> trains;
    for (const Train& train : trains_)
        trains.push_back(onTrack(train));
    for (const Accident& accident : watch_.collisions(trains))
        report(accident);
    for (const Train& train : trains_)
        if (const std::optional<Accident> accident = watch_.switchedUnder(onTrack(train), turnouts_))
            report(*accident);
}

void TrainMovement::report(const Accident& accident) {
    for (Train& train : trains_)
        if (std::ranges::find(accident.trains, train.locId) != accident.trains.end())
            derail(train);
    emit this->accident(accident);
}

// The train stops where it is and stays there: its speed forced to 0 on the station, as a controller would
// stop it, and no command moves it until it is placed again.
void TrainMovement::derail(Train& train) {
    if (train.derailed)
        return;
    train.derailed = true;
    station_.receive(cs2::encode(cs2::request(cs2::LocoSpeed{cs2::LocId(train.locId), std::uint16_t(0)})));
}

void TrainMovement::updateContacts(Train& train) {
    std::set<ContactKey> now = train.run.contactsCovered(graph_);
    for (const ContactKey& contact : now)
        if (!train.contacts.contains(contact))
            occupy(contact, train.locId);
    std::vector<ContactKey> left;
    for (const ContactKey& contact : train.contacts)
        if (!now.contains(contact))
            left.push_back(contact);
    train.contacts = std::move(now);
    for (const ContactKey& contact : left)
        release(contact);
}

void TrainMovement::occupy(const ContactKey& contact, std::uint32_t locId) {
    if (occupants_[contact]++ == 0)
        station_.setContact(std::uint16_t(contact.device), std::uint16_t(contact.number), true);
    emit occupantChanged(std::uint16_t(contact.device), std::uint16_t(contact.number), locId); // the last in
}

void TrainMovement::release(const ContactKey& contact) {
    if (--occupants_[contact] == 0)
        station_.setContact(std::uint16_t(contact.device), std::uint16_t(contact.number), false);
    emit occupantChanged(std::uint16_t(contact.device), std::uint16_t(contact.number), occupantOf(contact));
}

std::uint32_t TrainMovement::occupantOf(const ContactKey& contact) const {
    for (const Train& train : trains_)
        if (train.contacts.contains(contact))
            return train.locId;
    return 0;
}

std::uint32_t TrainMovement::occupantOf(std::uint16_t device, std::uint16_t contact) const {
    return occupantOf(ContactKey{device, contact});
}

bool TrainMovement::occupied(std::uint16_t device, std::uint16_t contact) const {
    const auto found = occupants_.find(ContactKey{device, contact});
    return found != occupants_.end() && found->second > 0;
}

void TrainMovement::updateLoad() {
    int load = 0;
    if (station_.power() != SimulatedStation::Power::Stopped) {
        load = options_.idleLoadMilliampere;
        for (const Train& train : trains_) {
            const SimulatedLoco* loco = station_.loco(train.locId);
            if (station_.power() == SimulatedStation::Power::Running && loco && loco->speed > 0 &&
                !train.derailed)
                load += options_.runningLoadMilliampere +
                        int(std::lround(loco->speed / 1000.0 * options_.topSpeedLoadMilliampere));
        }
    }
    if (load != load_) {
        load_ = load;
        station_.setTrackLoad(load);
    }
}

std::string TrainMovement::nameOf(std::uint32_t locId) const {
    const cs2config::Locomotive* loco = station_.layout().locomotives().find(locId);
    return loco && !loco->name.empty() ? loco->name : cs2::locomotiveText(cs2::LocId(locId));
}

TrainOnTrack TrainMovement::onTrack(const Train& train) const {
    return {train.locId, train.name, &train.run, train.derailed};
}

std::optional<TrainPosition> TrainMovement::position(std::uint32_t locId) const {
    const auto found = std::ranges::find(trains_, locId, &Train::locId);
    if (found == trains_.end())
        return std::nullopt;
    TrainPosition position;
    const RunSpan& front = found->run.spans().front();
    position.block = front.block;
    position.towards = front.towards;
    const double into = found->run.frontMm();
    position.frontMm = int(
        std::lround(front.isBlock() && front.towards == trackgraph::End::A ? front.lengthMm - into : into));
    position.headingAhead = found->headingAhead;
    position.derailed = found->derailed;
    for (const RunSpan& span : found->run.spans())
        if (span.isBlock())
            position.blocks.push_back(span.block);
    return position;
}

} // namespace stellwerk::sim
