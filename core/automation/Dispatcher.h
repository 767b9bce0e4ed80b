#pragma once

#include "automation/AutomationEvent.h"
#include "automation/PathChoice.h"
#include "automation/Reservations.h"
#include "automation/SpeedProfile.h"
#include "automation/Tracking.h"
#include "automation/Train.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stellwerk::automation {

// Milliseconds on the automation's clock (the driver's steady clock, or a test's simulated one).
using Millis = std::int64_t;

// The automation's decisions, in plain C++ on the track graph: trains placed and tracked, ways chosen and
// reserved, turnouts set and confirmed before a train departs, travel, creep and stop, and every fault
// stopping what it must. It is told what the railway reports and answers with commands and events; the
// driver (Automation) carries the commands out on the model and runs the clock.
class Dispatcher {
public:
    struct Options {
        SpeedProfile speeds;
        Millis dwell = 2000;         // standing at a stop before looking for the next way
        Millis settle = 300;         // after the last turnout's confirmation, before departing (it moves)
        Millis switchTimeout = 3000; // for one turnout command to be confirmed
        int switchAttempts = 3;      // then the way is given back and the train is at fault
        Millis retry = 500;          // looking again for a way when none was free
        int creepMm = 120;           // a block with one contact: the last millimetres at creep speed
        int stopMarginMm = 90;       // and the front stops this far before the block's far end
        int signalProceed = 1;       // a signal's position for proceed (Hp1, green) and for stop (Hp0, red)
        int signalStop = 0;
        Millis prepare = 1500; // at a schedule's stop: the next way is set this long before it departs
    };

    explicit Dispatcher(const trackgraph::TrackGraph& graph) : Dispatcher(graph, Options{}) {}
    Dispatcher(const trackgraph::TrackGraph& graph, Options options);

    // Puts a train in the block holding the contact (its number, of any feedback device), facing `towards`;
    // the sentence says why not.
    std::optional<std::string> place(std::uint32_t locId, const std::string& name, int lengthMm,
                                     std::int64_t contact, trackgraph::End towards);
    // The same by the block's id (the plan places by block): a train placed before is taken from where it
    // was, with everything it held.
    std::optional<std::string> placeInBlock(std::uint32_t locId, const std::string& name, int lengthMm,
                                            int block, trackgraph::End towards);
    // Takes a train off the railway: it is no longer tracked or driven, and everything it held is given
    // back; false when it was not placed.
    bool remove(std::uint32_t locId);
    void setMode(std::uint32_t locId, TrainMode mode, Millis now);
    // The train runs to the schedule's stops in turn (from its `next`), standing at each for its dwell; the
    // sentence says why not (a block no track plan block is named). A schedule without stops takes the
    // train's schedule away (it runs to any free block again).
    std::optional<std::string> setSchedule(std::uint32_t locId, Schedule schedule);
    // A push-pull train may change direction in any block when it finds no way on forwards; any other
    // train only at a terminus (no way leads on from the end it faces: buffer stops), and only when a
    // schedule sends it on.
    void setPushPull(std::uint32_t locId, bool pushPull);
    // Somebody else commanded the automatic train's speed or direction (`by` says who): it is manual at
    // once, nothing more is sent to it, and every block and way it holds stays reserved for it.
    void takenByHand(std::uint32_t locId, const std::string& by);
    // A manual train handed back where it stands: the way it held ahead is given back, it stops and looks
    // for a new one.
    void handBack(std::uint32_t locId, Millis now);

    // What the railway reports.
    void occupancyRead(const std::set<trackgraph::ContactKey>& occupied);
    void contactChanged(const trackgraph::ContactKey& contact, bool occupied, Millis now);
    void turnoutSwitched(std::int64_t article, int position, bool acknowledged, Millis now);
    void turnoutReported(std::int64_t article, int position, Millis now);
    // Timers: departures, braking, stops, dwells, lost trains, turnouts not confirmed.
    void tick(Millis now);

    // Every automatic train stops at its next stop and stays there, manual: a standing one at once (its
    // way ahead given back), a running one once it has arrived (Stopped event). Started again one by one.
    void stopAtNextStop(Millis now);

    // STOP (or track power off): every automatic train stops, and nothing starts again until resume().
    void halt(const std::string& why);
    // The station went silent: nothing can be sent; every automatic train is stopped as far as anyone
    // knows (Unknown). When it is back, occupancyRead() first, then stationBack(); trains stay stopped
    // until resume().
    void stationLost();
    // The station answers again: every train that was driven when it fell silent is told to stop (the
    // station may have kept it running: a stop is the one command that is safe whatever it did meanwhile;
    // nothing given up is sent again), and stays stopped-unknown until resume().
    void stationBack();
    void resume(Millis now);
    // The end of a run: every automatic train stopped, every reservation but the track it stands on given
    // back.
    void finish();

    bool paused() const { return paused_; }
    const std::map<std::uint32_t, Train>& trains() const { return trains_; }
    const Train* train(std::uint32_t locId) const;
    const Tracking& tracking() const { return tracking_; }
    const Reservations& reservations() const { return reservations_; }
    const trackgraph::TrackGraph& graph() const { return graph_; }
    const Options& options() const { return options_; }
    int blockMoves() const { return blockMoves_; }
    int faults() const { return faults_; }
    // The worst departure from a schedule's stop later or earlier than its dwell says, of those whose way
    // was free in time (a train waiting for a free way is not late by the dwell).
    Millis worstDwellError() const { return worstDwellError_; }
    // What the railway should do, and what happened, since the last call.
    std::vector<DriveCommand> takeCommands();
    std::vector<AutomationEvent> takeEvents();

private:
    // An automatic train's journey to its destination.
    struct Journey {
        Path path;
        std::size_t next = 0;                 // index of the next block to enter
        std::map<std::int64_t, int> pending;  // turnouts not confirmed yet: position
        std::map<std::int64_t, int> attempts; // commands sent per turnout
        Millis switchDeadline = 0, departAt = -1, brakeAt = -1, stopAt = -1, lostAt = -1;
        Millis dwellUntil = 0, nextTry = 0;
        int stopFrontMm = 0;    // a stop by the distance: where the front stops in its block
        Millis dwellFrom = -1;  // standing at a schedule's stop since then
        bool wayInTime = false; // its way was set before the dwell ended
    };

    // Tracking (Dispatcher.cpp).
    std::optional<NextBlock> expectedNext(std::uint32_t locId) const;
    std::optional<NextBlock> followedNext(std::uint32_t locId) const;
    void sighted(const Sighting& sighting, Millis now);
    void entered(const Sighting& sighting, Millis now);
    void ghostSeen(int block);
    std::optional<std::uint32_t> overrunBy(int block) const;
    void releaseBehind(std::uint32_t locId);
    TrackState stateFor(std::uint32_t locId) const;
    // Driving (DispatcherDriving.cpp).
    void driveTick(Train& train, Journey& journey, Millis now);
    void lookForWay(Train& train, Journey& journey, Millis now);
    void sendSwitching(Journey& journey, std::int64_t article, int position, Millis now);
    void turnoutsTimedOut(Train& train, Journey& journey, Millis now);
    void depart(Train& train, Journey& journey, Millis now);
    void frontMoved(Train& train, Journey& journey, int block, int contactIndex, Millis now);
    void approachStop(Train& train, Journey& journey, int block, Millis now);
    void brake(Train& train);
    void arrive(Train& train, Journey& journey, Millis now);
    void reachedStop(Train& train, Journey& journey, int block, Millis now);
    void holdAtStop(Train& train, int block);
    // A way on, and whether the train must change direction first.
    struct Way {
        Path path;
        bool turn = false;
    };
    std::optional<Way> wayFor(Train& train, Journey& journey, Millis now);
    std::optional<Path> wayFrom(const Train& train, const trackgraph::BlockEnd& front) const;
    bool mayTurn(const Train& train, const trackgraph::BlockEnd& front) const;
    void turn(Train& train);
    void stopTrain(Train& train, TrainState state, AutomationEvent::Kind kind, const std::string& why);
    // Stopped by a fault: the event carries the reason in parts and its English sentence.
    void stopTrain(Train& train, TrainState state, AutomationEvent::Kind kind, StopReason reason);
    // The signals at the start of a departing train's way show proceed; behind it (or when it stops, or
    // is no longer the automation's) they show stop again.
    void clearSignals(const Train& train);
    void signalsToStop(std::uint32_t locId);
    void giveBackWay(std::uint32_t locId);
    Millis expectNextContact(const Train& train, const Journey& journey, Millis now) const;
    // Output.
    void command(DriveCommand command) { commands_.push_back(command); }
    void event(AutomationEvent::Kind kind, std::uint32_t locId, int block, std::string text,
               StopReason reason = {});
    std::string blockName(int block) const;

    const trackgraph::TrackGraph& graph_;
    Options options_;
    Tracking tracking_;
    Reservations reservations_;
    PathChoice choice_;
    std::map<std::uint32_t, Train> trains_;
    std::map<std::uint32_t, Journey> journeys_;
    std::map<std::int64_t, int> positions_; // turnouts as the railway reports them
    std::set<std::uint32_t> mustBeSeen_;    // ran or were seen when the station fell silent
    std::set<std::uint32_t> stopAtStop_;    // running on to their next stop, then manual (stopAtNextStop)
    std::map<std::uint32_t, std::vector<std::int64_t>> cleared_; // signals showing proceed for a train
    bool paused_ = false;
    int blockMoves_ = 0;
    int faults_ = 0;
    Millis worstDwellError_ = 0;
    std::vector<DriveCommand> commands_;
    std::vector<AutomationEvent> events_;
};

} // namespace stellwerk::automation
