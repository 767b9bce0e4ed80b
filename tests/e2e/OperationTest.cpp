// The desktop's automatic operation (operation::Operation) on the simulated CS2 over a real TCP socket, as
// the window holds it: the layout in use set from the station's download, a new railway for every session,
// the book of trains in a folder of the test's own. Real trains run automatically; the simulator's accident
// counters are the referee. STOP halts, GO does not resume; a new railway places the trains again from the
// book and nothing moves until Resume; "stop all at their next stop" leaves every train standing, manual.

#include "operation/Operation.h"

#include "E2eSupport.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "sim/TrainMovement.h"
#include "station/StartupSequence.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace stellwerk::e2e {
namespace {

using automation::AutomationEvent;
using automation::TrainMode;
using automation::TrainState;
using Kind = automation::AutomationEvent::Kind;
using trackgraph::End;

constexpr std::uint32_t Br218 = 0x4001, Ice = 0x4002, V100 = 0x0018;

class OperationRig {
public:
    static constexpr std::chrono::milliseconds Step{50};

    OperationRig() : rig(Wire::Tcp) {}
    ~OperationRig() {
        operation.reset();
        railway.reset();
        startup.reset();
    }

    // The simulator's trains, the station read, the track power on and the Operation made.
    bool start(const std::vector<sim::TrainPlacement>& placements) {
        movement = std::make_unique<sim::TrainMovement>(rig.station, placements);
        QObject::connect(movement.get(), &sim::TrainMovement::accident,
                         [this](const sim::Accident& accident) { accidents.push_back(accident.text); });
        movement->start();
        movement->stop(); // the test runs its clock
        if (!rig.start() || !newRailway())
            return false;
        railway->go();
        return waitFor([&] { return railway->power() == station::PowerState::Running; });
    }
    // As the binding does for a new session: a new railway, handed over before its start-up, the old one
    // deleted, then loaded and the layout in use set from the download.
    bool newRailway() {
        auto next = std::make_unique<model::Railway>(*rig.session);
        QObject::connect(next.get(), &model::Railway::locomotiveCommandSent, [this] { ++commandsInFlight; });
        QObject::connect(next.get(), &model::Railway::locomotiveCommandAcknowledged,
                         [this] { --commandsInFlight; });
        QObject::connect(next.get(), &model::Railway::locomotiveCommandFailed,
                         [this] { --commandsInFlight; });
        if (!operation) {
            operation::Operation::Options options;
            options.dataDir = dataDir.path().toStdString();
            options.tick = std::chrono::milliseconds(0);
            options.clock = [this] { return now; };
            options.dispatcher.dwell = 1000;
            operation = std::make_unique<operation::Operation>(layout, options);
            operation->setStationName([] { return std::string("tcp://127.0.0.1"); });
            QObject::connect(operation.get(), &operation::Operation::happened,
                             [this](const AutomationEvent& event) { events.push_back(event); });
        }
        commandsInFlight = 0;
        operation->setRailway(next.get());
        railway = std::move(next);
        station::StartupOptions startupOptions;
        startupOptions.readStatusData = false;
        startup = std::make_unique<station::StartupSequence>(*rig.session, startupOptions);
        bool ready = false;
        QObject::connect(startup.get(), &station::StartupSequence::ready,
                         [&](const station::StartupResult& result) {
                             railway->load(result);
                             layout.useStationDownload(result);
                             ready = true;
                         });
        startup->start();
        return waitFor([&] { return ready; }, 4 * WaitMs) && settle();
    }
    void run(std::chrono::milliseconds duration) {
        for (auto elapsed = std::chrono::milliseconds(0); elapsed < duration; elapsed += Step) {
            movement->advance(Step);
            now += Step.count();
            settle();
            operation->automation()->tick();
            settle();
        }
    }
    bool settle() {
        return waitFor(
            [&] {
                const automation::Automation* automation = operation->automation();
                return commandsInFlight <= 0 && (!automation || automation->switchingsInFlight() == 0) &&
                       contactsInStep();
            },
            2000);
    }
    bool contactsInStep() const {
        if (!operation->automation())
            return true;
        for (const trackgraph::Block& block : dispatcher().graph().blocks())
            for (const trackgraph::ContactOnBlock& on : block.contacts) {
                const auto device = std::uint16_t(on.contact.device),
                           number = std::uint16_t(on.contact.number);
                const model::FeedbackContact* contact = railway->contact(model::contactKey(device, number));
                if ((contact && contact->known() && contact->occupied()) !=
                    rig.station.contact(device, number))
                    return false;
            }
        return true;
    }
    const automation::Dispatcher& dispatcher() const { return operation->automation()->dispatcher(); }
    int block(const std::string& name) const {
        for (const trackgraph::Block& block : dispatcher().graph().blocks())
            if (block.name == name)
                return block.id;
        ADD_FAILURE() << "no block " << name;
        return 0;
    }
    int count(Kind kind, std::size_t from = 0) const {
        int n = 0;
        for (std::size_t i = from; i < events.size(); ++i)
            n += events[i].kind == kind;
        return n;
    }
    std::string eventLog() const {
        std::string log;
        for (const AutomationEvent& event : events)
            log += std::string(automation::eventKindName(event.kind)) + ": " + event.text + "\n";
        return log;
    }
    // The three demo trains placed (as the simulator has them) and started one by one.
    void placeAndStartThree() {
        ASSERT_FALSE(operation->place(Br218, block("Gleis 1"), End::B, 200, false));
        ASSERT_FALSE(operation->place(Ice, block("Block 2"), End::B, 200, false));
        ASSERT_FALSE(operation->place(V100, block("Gleis 2"), End::B, 200, false));
        for (const std::uint32_t locId : {Br218, Ice, V100})
            ASSERT_FALSE(operation->start(locId));
    }

    QTemporaryDir dataDir;
    Rig rig;
    model::LayoutInUse layout;
    std::unique_ptr<sim::TrainMovement> movement;
    std::unique_ptr<model::Railway> railway;
    std::unique_ptr<station::StartupSequence> startup;
    std::unique_ptr<operation::Operation> operation;
    std::vector<AutomationEvent> events;
    std::vector<std::string> accidents;
    automation::Millis now = 0;
    int commandsInFlight = 0;
};

std::vector<sim::TrainPlacement> threeTrains() {
    return {{Br218, 1, End::B}, {Ice, 4, End::B}, {V100, 2, End::B}};
}

// A train placed through the Operation stands until it is started; started, three trains run a simulated
// minute without an accident.
TEST(Operation, PlacedTrainsStandUntilStartedThenRunWithoutAccident) {
    OperationRig rig;
    ASSERT_TRUE(rig.start(threeTrains()));
    ASSERT_NE(rig.operation->automation(), nullptr);
    ASSERT_FALSE(rig.operation->place(Br218, rig.block("Gleis 1"), End::B, 200, false));
    rig.run(std::chrono::seconds(5));
    EXPECT_EQ(rig.count(Kind::Departed), 0) << rig.eventLog();
    EXPECT_EQ(rig.rig.station.loco(Br218)->speed, 0);
    EXPECT_EQ(rig.dispatcher().train(Br218)->mode, TrainMode::Manual);

    ASSERT_FALSE(rig.operation->place(Ice, rig.block("Block 2"), End::B, 200, false));
    ASSERT_FALSE(rig.operation->place(V100, rig.block("Gleis 2"), End::B, 200, false));
    for (const std::uint32_t locId : {Br218, Ice, V100})
        ASSERT_FALSE(rig.operation->start(locId));
    rig.run(std::chrono::seconds(60));
    EXPECT_TRUE(rig.accidents.empty()) << rig.accidents.front() << "\n" << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0);
    EXPECT_EQ(rig.dispatcher().faults(), 0) << rig.eventLog();
    EXPECT_GE(rig.dispatcher().blockMoves(), 8) << rig.eventLog();
}

// STOP halts every automatic train; GO does not start them again; a restart (a new railway) places them
// again from the book where they stood, and they stand until Resume, then run on without an accident.
TEST(Operation, StopHaltsGoDoesNotResumeANewRailwayPlacesFromTheBookAndWaitsForResume) {
    OperationRig rig;
    ASSERT_TRUE(rig.start(threeTrains()));
    rig.placeAndStartThree();
    rig.run(std::chrono::seconds(20));
    ASSERT_GT(rig.dispatcher().blockMoves(), 0) << rig.eventLog();

    rig.railway->stop();
    rig.run(std::chrono::seconds(3));
    EXPECT_TRUE(rig.dispatcher().paused());
    EXPECT_TRUE(rig.operation->halted());
    rig.railway->go();
    ASSERT_TRUE(waitFor([&] { return rig.railway->power() == station::PowerState::Running; }));
    const std::size_t afterGo = rig.events.size();
    rig.run(std::chrono::seconds(5));
    EXPECT_EQ(rig.count(Kind::Departed, afterGo), 0) << rig.eventLog();
    for (const std::uint32_t locId : {Br218, Ice, V100})
        EXPECT_EQ(rig.rig.station.loco(locId)->speed, 0) << locId;

    std::map<std::uint32_t, int> stood;
    for (const std::uint32_t locId : {Br218, Ice, V100})
        stood[locId] = rig.dispatcher().tracking().body(locId)->frontBlock;
    int made = 0;
    QObject::connect(rig.operation.get(), &operation::Operation::automationChanged,
                     [&made](automation::Automation* automation) { made += automation != nullptr; });
    ASSERT_TRUE(rig.newRailway());
    ASSERT_GE(made, 1);
    ASSERT_NE(rig.operation->automation(), nullptr);
    ASSERT_EQ(rig.dispatcher().trains().size(), 3u);
    for (const std::uint32_t locId : {Br218, Ice, V100}) {
        EXPECT_EQ(rig.dispatcher().tracking().body(locId)->frontBlock, stood[locId]) << locId;
        EXPECT_TRUE(rig.operation->waitsForResume(locId))
            << locId << " " << rig.operation->notPlaced(locId) << rig.eventLog();
        EXPECT_EQ(rig.dispatcher().train(locId)->mode, TrainMode::Manual) << locId;
    }
    const std::size_t afterRestart = rig.events.size();
    rig.run(std::chrono::seconds(5));
    EXPECT_EQ(rig.count(Kind::Departed, afterRestart), 0) << rig.eventLog();

    ASSERT_FALSE(rig.operation->resume());
    rig.run(std::chrono::seconds(40));
    EXPECT_GT(rig.count(Kind::Departed, afterRestart), 0) << rig.eventLog();
    EXPECT_GT(rig.dispatcher().blockMoves(), 0) << rig.eventLog();
    EXPECT_TRUE(rig.accidents.empty()) << rig.accidents.front() << "\n" << rig.eventLog();
    EXPECT_EQ(rig.dispatcher().faults(), 0) << rig.eventLog();
}

// One call: every automatic train runs on to its next stop and stays there, manual; nothing moves after.
TEST(Operation, StopAllAtTheirNextStopLeavesEveryTrainStandingManual) {
    OperationRig rig;
    ASSERT_TRUE(rig.start(threeTrains()));
    rig.placeAndStartThree();
    for (int i = 0; i < 400 && rig.count(Kind::Departed) < 2; ++i)
        rig.run(OperationRig::Step);
    ASSERT_GE(rig.count(Kind::Departed), 2) << rig.eventLog();
    rig.operation->stopAllAtNextStop();
    rig.run(std::chrono::seconds(30));
    for (const std::uint32_t locId : {Br218, Ice, V100}) {
        const automation::Train* train = rig.dispatcher().train(locId);
        EXPECT_EQ(train->mode, TrainMode::Manual) << locId << "\n" << rig.eventLog();
        EXPECT_EQ(train->state, TrainState::Stopped) << locId;
        EXPECT_EQ(rig.rig.station.loco(locId)->speed, 0) << locId;
        EXPECT_FALSE(rig.operation->book().find(locId)->automatic) << locId;
    }
    const int moves = rig.dispatcher().blockMoves();
    rig.run(std::chrono::seconds(10));
    EXPECT_EQ(rig.dispatcher().blockMoves(), moves) << rig.eventLog();
    EXPECT_TRUE(rig.accidents.empty());
    EXPECT_EQ(rig.dispatcher().faults(), 0) << rig.eventLog();
}

// The plan places and takes off trains through the automation itself (its block menu): the book follows, so
// that a train taken off there is not placed again after a restart.
TEST(Operation, TheBookFollowsTrainsPlacedAndTakenOffOnThePlan) {
    OperationRig rig;
    ASSERT_TRUE(rig.start(threeTrains()));
    automation::Automation* automation = rig.operation->automation();
    ASSERT_NE(automation, nullptr);
    ASSERT_FALSE(automation->placeInBlock(V100, rig.block("Gleis 2"), End::A, 300));
    ASSERT_NE(rig.operation->book().find(V100), nullptr);
    EXPECT_EQ(rig.operation->book().find(V100)->lengthMm, 300);
    EXPECT_EQ(rig.operation->book().find(V100)->towards, End::A);

    ASSERT_TRUE(automation->remove(V100));
    EXPECT_EQ(rig.operation->book().find(V100), nullptr);
    ASSERT_TRUE(rig.newRailway());
    ASSERT_NE(rig.operation->automation(), nullptr);
    EXPECT_EQ(rig.dispatcher().train(V100), nullptr) << "taken off on the plan, not placed again";
}

} // namespace
} // namespace stellwerk::e2e
