#pragma once

#include "automation/Dispatcher.h"
#include "cs2/Messages.h"
#include "trackgraph/TrackGraph.h"

#include <QObject>
#include <QTimer>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace stellwerk::model {
class Locomotive;
class Railway;
struct Correction;
} // namespace stellwerk::model

namespace stellwerk::automation {

// Runs the Dispatcher on a railway: tells it every contact, turnout report and switching result, the
// station's STOP and silence, runs its clock, and carries out its commands through the railway (turnouts
// through the station or the device bound to them, speeds, track power off). The track graph is the layout
// in use's (the start-up's download or a folder); it must outlive the automation.
class Automation final : public QObject {
    Q_OBJECT

public:
    using Clock = std::function<Millis()>;

    Automation(model::Railway& railway, const trackgraph::TrackGraph& graph, Dispatcher::Options options = {},
               QObject* parent = nullptr);
    ~Automation() override;

    // A clock of the tests' own (simulated time); the default is the steady clock. Set before start().
    void setClock(Clock clock) { clock_ = std::move(clock); }
    // Puts a locomotive of the railway in the block holding the contact; the sentence says why not.
    std::optional<std::string> place(std::uint32_t locId, std::int64_t contact, trackgraph::End towards,
                                     int lengthMm = 200);
    // The same by the track graph's block id (the plan places by block); a train placed before is moved.
    std::optional<std::string> placeInBlock(std::uint32_t locId, int block, trackgraph::End towards,
                                            int lengthMm = 200);
    // Takes the train off the railway (stopped if the automation drove it); false when it was not placed.
    bool remove(std::uint32_t locId);
    void setPushPull(std::uint32_t locId, bool pushPull) { dispatcher_.setPushPull(locId, pushPull); }
    // The placed train's schedule; the sentence says why not.
    std::optional<std::string> setSchedule(std::uint32_t locId, Schedule schedule) {
        return dispatcher_.setSchedule(locId, std::move(schedule));
    }
    // Reads the occupancy, hands every placed train to the automation and starts the clock (tick every
    // `interval`; 0: the caller calls tick()).
    void start(std::chrono::milliseconds interval = std::chrono::milliseconds(20));
    void tick();
    // For a program that hands trains over one by one (the desktop): reads the occupancy and starts the
    // clock, and hands no train over. While the track power is known to be off, automation stays halted.
    void run(std::chrono::milliseconds interval = std::chrono::milliseconds(20));
    // The user resumes after STOP, a fault or the station's return.
    void resume();
    // A manual train (a throttle took it) handed back to the automation where it stands.
    void handBack(std::uint32_t locId);
    // The user stops one train: it becomes manual and stands; its blocks and way stay reserved for it.
    void stopByHand(std::uint32_t locId, const std::string& by);
    // Every automatic train stops at its next stop and stays there, manual (Dispatcher::stopAtNextStop).
    void stopAtNextStop();
    // Stops every train it drove and gives back every reservation but the track they stand on.
    void finish();

    const Dispatcher& dispatcher() const { return dispatcher_; }
    // Turnout commands sent and not answered yet (by the station or the device).
    int switchingsInFlight() const { return switchings_; }

signals:
    void happened(const stellwerk::automation::AutomationEvent& event);

private:
    void contactsChanged(const QList<quint32>& keys);
    void accessoriesChanged(const QList<qint64>& ids);
    void stateReportedChanged(bool reported);
    void commandSent(quint32 loco, int control);
    void locomotivesChanged(const QList<quint32>& ids);
    bool heardOwnCommand(std::uint32_t locId, const model::Locomotive& loco);
    void speedAnswered(std::uint32_t locId, bool confirmed);
    void corrected(const model::Correction& correction);
    void reverse(std::uint32_t locId);
    std::set<trackgraph::ContactKey> occupiedContacts();
    std::string trainName(std::uint32_t locId) const;
    void carryOut();

    model::Railway& railway_;
    Dispatcher dispatcher_;
    Clock clock_;
    QTimer timer_;
    std::map<quint32, bool> occupied_; // as last told to the dispatcher
    int switchings_ = 0;
    // What this automation told a locomotive: speeds sent and not heard back yet, the last one sent and
    // the last one heard, the direction. A change heard on the bus that is none of them is another
    // controller's.
    struct Told {
        std::deque<int> unheard; // in the order sent; each leaves with the station's answer to it
        int speed = 0;
        int heard = 0; // the last of them the station confirmed
        std::optional<cs2::Direction> direction;
        std::optional<cs2::Direction> turnedFrom; // until the direction it was turned to is heard
    };
    std::map<std::uint32_t, Told> told_;
    bool commanding_ = false; // the railway's locomotive commands now are this automation's
    // Corrections the railway announced and has not sent yet, per locomotive and control.
    std::map<std::pair<std::uint32_t, int>, int> correcting_;
};

} // namespace stellwerk::automation
