#include "sim/TrainMovement.h"

#include "sim/SimulatedStation.h"

#include <algorithm>
#include <cmath>

namespace stellwerk::sim {

namespace {

constexpr std::uint8_t Backward = 2; // SimulatedLoco::direction, document 3.5

} // namespace

TrainMovement::TrainMovement(SimulatedStation& station, TrainTrack track, Options options, QObject* parent)
    : QObject(parent), station_(station), track_(std::move(track)), options_(options),
      occupants_(track_.sections.size(), 0) {
    timer_.setInterval(options_.tick);
    connect(&timer_, &QTimer::timeout, this, [this] { advance(options_.tick); });
}

TrainMovement::TrainMovement(SimulatedStation& station, TrainTrack track, QObject* parent)
    : TrainMovement(station, std::move(track), Options{}, parent) {}

void TrainMovement::start() {
    if (!placed_) {
        for (const TrainPlacement& placement : track_.placements)
            place(placement);
        placed_ = true;
    }
    updateLoad();
    timer_.start();
}

void TrainMovement::stop() {
    timer_.stop();
}

void TrainMovement::place(const TrainPlacement& placement) {
    if (placement.section < 0 || std::size_t(placement.section) >= track_.sections.size())
        return;
    Train train;
    train.locId = placement.locId;
    train.sections.push_back(placement.section);
    // The whole train stands in its section.
    const double length = lengthOf(placement.section);
    train.frontMm =
        std::clamp(double(placement.offsetMm), std::min(double(options_.trainLengthMm), length), length);
    trains_.push_back(std::move(train));
    occupy(placement.section, placement.locId);
}

void TrainMovement::advance(std::chrono::milliseconds elapsed) {
    if (station_.power() == SimulatedStation::Power::Running) {
        for (Train& train : trains_) {
            const SimulatedLoco* loco = station_.loco(train.locId);
            if (!loco)
                continue;
            const bool ahead = train.runsAheadForward != (loco->direction == Backward);
            if (ahead != train.headingAhead)
                turnAround(train);
            if (loco->speed > 0)
                move(train,
                     loco->speed / 1000.0 * options_.topSpeedMmPerSecond * double(elapsed.count()) / 1000.0);
        }
    }
    updateLoad();
}

void TrainMovement::move(Train& train, double distanceMm) {
    train.frontMm += distanceMm;
    while (train.frontMm > lengthOf(train.sections.front())) {
        if (!enterNext(train)) {
            train.frontMm = lengthOf(train.sections.front()); // stands at the buffer stop
            break;
        }
    }
    releaseTail(train);
}

bool TrainMovement::enterNext(Train& train) {
    const int next = nextSection(train);
    if (next == SectionExit::BufferStop)
        return false;
    train.frontMm -= lengthOf(train.sections.front());
    train.sections.push_front(next);
    occupy(next, train.locId);
    return true;
}

// Releases the sections the rear end has left, as the contact of a section frees once the last axle is out.
void TrainMovement::releaseTail(Train& train) {
    double covered = train.frontMm;
    std::size_t keep = 1;
    while (keep < train.sections.size() && covered < options_.trainLengthMm)
        covered += lengthOf(train.sections[keep++]);
    while (train.sections.size() > keep) {
        const int left = train.sections.back();
        train.sections.pop_back();
        release(left);
    }
}

// The rear end becomes the front: the train now measures from the other end of its rearmost section.
void TrainMovement::turnAround(Train& train) {
    const double length = options_.trainLengthMm;
    double newFront = 0;
    if (train.sections.size() == 1) {
        newFront = lengthOf(train.sections.front()) - (train.frontMm - length);
    } else {
        double middle = 0;
        for (std::size_t i = 1; i + 1 < train.sections.size(); ++i)
            middle += lengthOf(train.sections[i]);
        newFront = length - train.frontMm - middle;
    }
    std::ranges::reverse(train.sections);
    train.frontMm = std::clamp(newFront, 0.0, lengthOf(train.sections.front()));
    train.headingAhead = !train.headingAhead;
}

int TrainMovement::nextSection(const Train& train) const {
    const FeedbackSection& section = track_.sections[std::size_t(train.sections.front())];
    const SectionExit& exit = train.headingAhead ? section.ahead : section.behind;
    if (exit.turnout == 0)
        return exit.next;
    const std::optional<std::uint8_t> position = station_.accessoryPosition(exit.turnout);
    return position && *position == exit.divergingPosition ? exit.diverging : exit.next;
}

void TrainMovement::occupy(int section, std::uint32_t locId) {
    const FeedbackSection& watched = track_.sections[std::size_t(section)];
    if (occupants_[std::size_t(section)]++ == 0)
        station_.setContact(watched.device, watched.contact, true);
    emit occupantChanged(watched.device, watched.contact, locId); // the train that came in last
}

void TrainMovement::release(int section) {
    const FeedbackSection& watched = track_.sections[std::size_t(section)];
    if (--occupants_[std::size_t(section)] == 0)
        station_.setContact(watched.device, watched.contact, false);
    emit occupantChanged(watched.device, watched.contact, occupantOf(section));
}

std::uint32_t TrainMovement::occupantOf(int section) const {
    for (const Train& train : trains_)
        if (std::find(train.sections.begin(), train.sections.end(), section) != train.sections.end())
            return train.locId;
    return 0;
}

void TrainMovement::updateLoad() {
    int load = 0;
    if (station_.power() != SimulatedStation::Power::Stopped) {
        load = options_.idleLoadMilliampere;
        for (const Train& train : trains_) {
            const SimulatedLoco* loco = station_.loco(train.locId);
            if (station_.power() == SimulatedStation::Power::Running && loco && loco->speed > 0)
                load += options_.runningLoadMilliampere +
                        int(std::lround(loco->speed / 1000.0 * options_.topSpeedLoadMilliampere));
        }
    }
    if (load != load_) {
        load_ = load;
        station_.setTrackLoad(load);
    }
}

double TrainMovement::lengthOf(int section) const {
    return track_.sections[std::size_t(section)].lengthMm;
}

std::optional<TrainPosition> TrainMovement::position(std::uint32_t locId) const {
    for (const Train& train : trains_)
        if (train.locId == locId)
            return TrainPosition{train.sections.front(),
                                 int(std::lround(train.frontMm)),
                                 train.headingAhead,
                                 {train.sections.begin(), train.sections.end()}};
    return std::nullopt;
}

bool TrainMovement::occupied(int section) const {
    return section >= 0 && std::size_t(section) < occupants_.size() && occupants_[std::size_t(section)] > 0;
}

} // namespace stellwerk::sim
