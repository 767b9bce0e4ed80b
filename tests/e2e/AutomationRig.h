#pragma once

// Automatic trains on the simulated CS2, end to end: the station with its trains (sim::TrainMovement, its
// clock run by the test) behind a real TCP socket, and the app's side as a program holds it (session,
// start-up, Railway, Automation on the track graph of the layout in use: the downloaded plan). Simulated time
// runs in 50 ms steps; after each step the rig waits until the railway has heard every contact the simulator
// changed and the station has answered every command, so a run is as fast as the machine and as exact as the
// step.

#include "E2eSupport.h"
#include "automation/Automation.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "sim/TrainMovement.h"
#include "station/StartupSequence.h"

#include <QObject>
#include <map>
#include <memory>
#include <vector>

namespace stellwerk::e2e {

class AutomationRig {
public:
    static constexpr std::chrono::milliseconds Step{50};

    explicit AutomationRig(sim::StationLayout layout = sim::StationLayout::demo())
        : rig(Wire::Tcp, sessionSettings(), std::move(layout)) {}
    ~AutomationRig() {
        automation.reset();
        railway.reset();
        startup.reset();
    }

    // Places the simulator's trains, connects, reads the station, switches the track power on and places
    // the same trains for the automation (each "LOC=CONTACT:END" as the simulator has it).
    bool start(const std::vector<sim::TrainPlacement>& placements,
               automation::Dispatcher::Options options = fastOptions()) {
        movement = std::make_unique<sim::TrainMovement>(rig.station, placements);
        QObject::connect(movement.get(), &sim::TrainMovement::accident,
                         [this](const sim::Accident& accident) { accidents.push_back(accident.text); });
        movement->start();
        movement->stop(); // the test runs its clock
        if (!rig.start() || !readStation())
            return false;
        railway->go();
        if (!waitFor([&] { return railway->power() == station::PowerState::Running; }))
            return false;
        layout.useStationDownload(startup->result());
        graph = layout.graph();
        automation = std::make_unique<automation::Automation>(*railway, *graph, options);
        automation->setClock([this] { return now; });
        QObject::connect(automation.get(), &automation::Automation::happened,
                         [this](const automation::AutomationEvent& event) { events.push_back(event); });
        for (const sim::TrainPlacement& placement : placements)
            if (const auto problem =
                    automation->place(placement.locId, placement.contact, placement.towards)) {
                ADD_FAILURE() << *problem;
                return false;
            }
        return true;
    }
    // The start-up once more on the same railway, as a program does when the station is back.
    bool readAgain() {
        station::StartupOptions options;
        options.readStatusData = false;
        startup = std::make_unique<station::StartupSequence>(*rig.session, options);
        bool ready = false;
        QObject::connect(startup.get(), &station::StartupSequence::ready,
                         [&](const station::StartupResult& result) {
                             railway->load(result);
                             ready = true;
                         });
        startup->start();
        return waitFor([&] { return ready; }, 4 * WaitMs);
    }
    // Hands the placed trains to the automation (its clock is the rig's: tick() per step).
    void startAutomation() {
        automation->start(std::chrono::milliseconds(0));
        settle();
    }

    // Simulated time: the trains move a step, then the app hears it and answers, then the automation's clock.
    void run(std::chrono::milliseconds duration) {
        for (auto elapsed = std::chrono::milliseconds(0); elapsed < duration; elapsed += Step) {
            movement->advance(Step);
            now += Step.count();
            settle();
            automation->tick();
            settle();
        }
    }
    // Until the railway shows every contact as the station has it and every command was answered.
    bool settle() {
        return waitFor(
            [&] {
                return commandsInFlight == 0 && (!automation || automation->switchingsInFlight() == 0) &&
                       contactsInStep();
            },
            2000);
    }
    bool contactsInStep() const {
        for (const trackgraph::Block& block : graph->blocks())
            for (const trackgraph::ContactOnBlock& on : block.contacts) {
                const auto device = std::uint16_t(on.contact.device),
                           number = std::uint16_t(on.contact.number);
                const model::FeedbackContact* contact = railway->contact(model::contactKey(device, number));
                const bool shown = contact && contact->known() && contact->occupied();
                if (shown != rig.station.contact(device, number))
                    return false;
            }
        return true;
    }
    int count(automation::AutomationEvent::Kind kind, std::uint32_t locId = 0) const {
        int n = 0;
        for (const automation::AutomationEvent& event : events)
            n += event.kind == kind && (locId == 0 || event.locId == locId);
        return n;
    }
    std::string eventLog() const {
        std::string log;
        for (const automation::AutomationEvent& event : events)
            log += std::string(automation::eventKindName(event.kind)) + ": " + event.text + "\n";
        for (const std::string& problem : problems)
            log += "railway: " + problem + "\n";
        return log;
    }

    Rig rig;
    std::unique_ptr<sim::TrainMovement> movement;
    std::unique_ptr<model::Railway> railway;
    std::unique_ptr<station::StartupSequence> startup;
    model::LayoutInUse layout; // the station's download, as the program holds it
    std::shared_ptr<const trackgraph::TrackGraph> graph;
    std::unique_ptr<automation::Automation> automation;
    std::vector<automation::AutomationEvent> events;
    std::vector<std::string> accidents;
    std::vector<std::string> problems; // the railway's
    automation::Millis now = 0;
    int commandsInFlight = 0;

    // Short dwells, so that a few simulated minutes see many block moves.
    static automation::Dispatcher::Options fastOptions() {
        automation::Dispatcher::Options options;
        options.dwell = 1000;
        return options;
    }

private:
    bool readStation() {
        railway = std::make_unique<model::Railway>(*rig.session);
        QObject::connect(railway.get(), &model::Railway::locomotiveCommandSent,
                         [this] { ++commandsInFlight; });
        QObject::connect(railway.get(), &model::Railway::locomotiveCommandAcknowledged,
                         [this] { --commandsInFlight; });
        QObject::connect(railway.get(), &model::Railway::locomotiveCommandFailed,
                         [this] { --commandsInFlight; });
        return readAgain();
    }
};

} // namespace stellwerk::e2e
