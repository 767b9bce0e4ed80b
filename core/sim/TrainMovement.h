#pragma once

#include "sim/AccidentWatch.h"
#include "sim/TrainPlacement.h"
#include "sim/TrainRun.h"
#include "sim/TurnoutWatch.h"
#include "trackgraph/TrackGraph.h"

#include <QObject>
#include <QTimer>
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stellwerk::sim {

class SimulatedStation;

// Where a train is on the track graph.
struct TrainPosition {
    int block = 0;                                // the block its front is in (0: between blocks)
    int frontMm = 0;                              // there: its front's distance from end a
    trackgraph::End towards = trackgraph::End::B; // there: the end it runs to
    bool headingAhead = true;                     // running the way it was placed (else reversed)
    bool derailed = false;
    std::vector<int> blocks; // every block it is on, front first
};

// Makes the simulated layout come alive on the track graph of the station's own plan (blocks, the ways
// between them, the turnouts as the station has them set): locomotives the station runs move, occupy and
// release the S88 contacts their length covers as a Link-S88 reports them, suffer the accidents a real
// layout would (collision, buffer stop, turnout run through: the train stops, derailed, until it is placed
// again), and draw current from the track.
class TrainMovement : public QObject {
    Q_OBJECT

public:
    struct Options {
        std::chrono::milliseconds tick{100};
        int topSpeedMmPerSecond =
            500;                 // at system speed 1000 (about 160 km/h in H0); speed s runs s/1000 of it
        int trainLengthMm = 200; // lokomotive.cs2 has no length: every train is this long
        int idleLoadMilliampere = 120; // decoders and lights on the track while nothing runs
        int runningLoadMilliampere = 200;
        int topSpeedLoadMilliampere = 450; // added at full speed
    };

    TrainMovement(SimulatedStation& station, std::vector<TrainPlacement> placements, Options options,
                  QObject* parent = nullptr);
    TrainMovement(SimulatedStation& station, std::vector<TrainPlacement> placements,
                  QObject* parent = nullptr);
    ~TrainMovement() override;

    // Places the trains given to the constructor (their contacts as S88 events), then moves them every tick.
    void start();
    void stop();
    // Moves every running train by what `elapsed` at its speed covers, in steps of at most 100 ms (tests
    // call this directly to run the clock faster).
    void advance(std::chrono::milliseconds elapsed);

    // Puts a locomotive on the track (again: a derailed one runs after this); the sentence says why not.
    std::optional<std::string> place(const TrainPlacement& placement);
    // What went wrong placing the constructor's trains.
    const std::vector<std::string>& problems() const { return problems_; }

    const trackgraph::TrackGraph& graph() const { return graph_; }
    std::size_t trainCount() const { return trains_.size(); }
    std::optional<TrainPosition> position(std::uint32_t locId) const;
    bool occupied(std::uint16_t device, std::uint16_t contact) const;
    // The Loc-ID of a train on the contact (0: none); of one of them when two are.
    std::uint32_t occupantOf(std::uint16_t device, std::uint16_t contact) const;
    const AccidentCounts& accidents() const { return watch_.counts(); }
    const std::vector<Accident>& accidentLog() const { return watch_.log(); }
    int trackLoad() const { return load_; }

signals:
    // A train came onto a contact, or one left it (locId: the train still on it, 0 when none is): what the
    // simulator knows and a real station cannot say, for the demo's track plan.
    void occupantChanged(std::uint16_t device, std::uint16_t contact, std::uint32_t locId);
    // An accident happened; the trains in it are derailed already.
    void accident(const stellwerk::sim::Accident& accident);

private:
    struct Train {
        std::uint32_t locId = 0;
        std::string name;
        TrainRun run;
        bool headingAhead = true;
        bool derailed = false;
        std::set<trackgraph::ContactKey> contacts;
    };

    void step(std::chrono::milliseconds elapsed);
    void move(Train& train, std::chrono::milliseconds elapsed);
    void watchTrains();
    void report(const Accident& accident);
    void derail(Train& train);
    void remove(std::uint32_t locId);
    void updateContacts(Train& train);
    void occupy(const trackgraph::ContactKey& contact, std::uint32_t locId);
    void release(const trackgraph::ContactKey& contact);
    void updateLoad();
    std::string nameOf(std::uint32_t locId) const;
    TrainOnTrack onTrack(const Train& train) const;
    std::uint32_t occupantOf(const trackgraph::ContactKey& contact) const;

    SimulatedStation& station_;
    Options options_;
    trackgraph::TrackGraph graph_;
    TurnoutWatch turnouts_;
    AccidentWatch watch_;
    std::vector<TrainPlacement> placements_;
    std::vector<std::string> problems_;
    std::vector<Train> trains_;
    std::map<trackgraph::ContactKey, int> occupants_; // trains per contact
    QTimer timer_;
    int load_ = -1;
    bool placed_ = false;
};

} // namespace stellwerk::sim
