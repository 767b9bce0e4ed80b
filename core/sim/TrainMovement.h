#pragma once

#include "sim/TrainTrack.h"

#include <QObject>
#include <QTimer>
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace stellwerk::sim {

class SimulatedStation;

// Where a train is: the section its front end is in and how far into it, in its direction of travel.
struct TrainPosition {
    int section = 0;
    int frontMm = 0;
    bool headingAhead = true;
    std::vector<int> occupiedSections; // front first
};

// Makes the simulated layout come alive: locomotives the station runs move along the track, occupy and
// release S88 contacts as a Link-S88 reports them, follow the turnouts and draw current from the track.
class TrainMovement : public QObject {
    Q_OBJECT

public:
    struct Options {
        std::chrono::milliseconds tick{100};
        int topSpeedMmPerSecond = 500; // at system speed 1000 (about 160 km/h in H0)
        int trainLengthMm = 250;       // every train; shorter than every section
        int idleLoadMilliampere = 120; // decoders and lights on the track while nothing runs
        int runningLoadMilliampere = 200;
        int topSpeedLoadMilliampere = 450; // added at full speed
    };

    TrainMovement(SimulatedStation& station, TrainTrack track, Options options, QObject* parent = nullptr);
    TrainMovement(SimulatedStation& station, TrainTrack track, QObject* parent = nullptr);

    // Reports the sections the placed trains occupy (S88 events), then moves them every tick.
    void start();
    void stop();
    // Moves every running train by what `elapsed` at its speed covers (tests call this directly).
    void advance(std::chrono::milliseconds elapsed);

    std::optional<TrainPosition> position(std::uint32_t locId) const;
    bool occupied(int section) const;
    // The Loc-ID of a train in the section (0: none); of one of them when two are.
    std::uint32_t occupantOf(int section) const;

signals:
    // A train came into the section of a contact, or one left it (locId: the train still in it, 0 when
    // none is): what the simulator knows and a real station cannot say, for the demo's track plan.
    void occupantChanged(std::uint16_t device, std::uint16_t contact, std::uint32_t locId);

public:
    const TrainTrack& track() const { return track_; }
    int trackLoad() const { return load_; }

private:
    struct Train {
        std::uint32_t locId = 0;
        std::deque<int> sections; // front first
        double frontMm = 0;       // how far the front end is into sections.front()
        bool headingAhead = true;
        bool runsAheadForward = true;
    };

    void place(const TrainPlacement& placement);
    void move(Train& train, double distanceMm);
    bool enterNext(Train& train);
    void releaseTail(Train& train);
    void turnAround(Train& train);
    int nextSection(const Train& train) const;
    void occupy(int section, std::uint32_t locId);
    void release(int section);
    void updateLoad();
    double lengthOf(int section) const;

    SimulatedStation& station_;
    TrainTrack track_;
    Options options_;
    std::vector<Train> trains_;
    std::vector<int> occupants_; // trains per section
    QTimer timer_;
    int load_ = -1;
    bool placed_ = false;
};

} // namespace stellwerk::sim
