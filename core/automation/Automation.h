#pragma once

#include "automation/Dispatcher.h"
#include "trackgraph/TrackGraph.h"

#include <QObject>
#include <QTimer>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace stellwerk::model {
class Railway;
}

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
    // Reads the occupancy, hands every placed train to the automation and starts the clock (tick every
    // `interval`; 0: the caller calls tick()).
    void start(std::chrono::milliseconds interval = std::chrono::milliseconds(20));
    void tick();
    // The user resumes after STOP, a fault or the station's return.
    void resume();
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
    std::set<trackgraph::ContactKey> occupiedContacts();
    void carryOut();

    model::Railway& railway_;
    Dispatcher dispatcher_;
    Clock clock_;
    QTimer timer_;
    std::map<quint32, bool> occupied_; // as last told to the dispatcher
    int switchings_ = 0;
};

} // namespace stellwerk::automation
