// Routes (document 8.2.4): a route switches its items in order, each after its `..sekunde` wait, runs
// the routes it references in place, and refuses to run a chain of references that comes back to itself.

#include "ModelBench.h"
#include "cs2/Codec.h"
#include "cs2config/Document.h"

#include <QElapsedTimer>
#include <QTest>

namespace stellwerk::model::test {
namespace {

// Every accessory switching the station received (on-commands), with the time it arrived.
struct SwitchLog {
    struct Entry {
        std::uint32_t address = 0;
        std::uint8_t output = 0;
        qint64 atMs = 0;
    };

    explicit SwitchLog(ModelBench& bench) {
        clock.start();
        QObject::connect(&bench.stationEnd, &transport::Transport::framesReceived, &context,
                         [this](const std::vector<can::CanFrame>& frames) {
                             for (const auto& frame : frames) {
                                 const auto message = cs2::decode(frame);
                                 const auto* sw =
                                     message ? std::get_if<cs2::AccessorySwitch>(&message->body) : nullptr;
                                 if (sw && !message->response && sw->current != 0)
                                     entries.push_back({sw->article.value(), sw->position, clock.elapsed()});
                             }
                         });
    }

    QObject context;
    QElapsedTimer clock;
    std::vector<Entry> entries;
};

class RouteRuns : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(bench.start()); }

    ModelBench bench;
};

TEST_F(RouteRuns, SwitchesTheStepsInOrderWithTheirDelays) {
    SwitchLog log(bench);
    QSignalSpy progressed(&bench.railway, &Railway::routeProgressed);
    QSignalSpy finished(&bench.railway, &Railway::routeFinished);
    ASSERT_TRUE(bench.railway.runRoute(1));
    EXPECT_TRUE(bench.railway.route(1)->running());
    ASSERT_TRUE(waitFor([&] { return finished.count() == 1; }));
    EXPECT_FALSE(bench.railway.route(1)->running());

    ASSERT_EQ(log.entries.size(), 3u);
    EXPECT_EQ(log.entries[0].address, 0x3000u); // W1
    EXPECT_EQ(log.entries[1].address, 0x3004u); // S5
    EXPECT_EQ(log.entries[2].address, 0x3002u); // W2, third position: second address, output 0
    EXPECT_EQ(log.entries[2].output, 0);
    EXPECT_GE(log.entries[1].atMs - log.entries[0].atMs, 250) << "..sekunde=0.3";
    EXPECT_GE(log.entries[2].atMs - log.entries[1].atMs, 150) << "..sekunde=0.2";
    EXPECT_EQ(progressed.count(), 3);
    EXPECT_EQ(progressed.last().at(1).toInt(), 3);
    EXPECT_EQ(bench.railway.accessory(1)->position(), 1);
    EXPECT_EQ(bench.railway.accessory(5)->position(), 1);
    EXPECT_EQ(bench.railway.accessory(2)->position(), 2);
}

TEST_F(RouteRuns, RunsAReferencedRouteInPlaceOfItsStep) {
    SwitchLog log(bench);
    QSignalSpy finished(&bench.railway, &Railway::routeFinished);
    ASSERT_TRUE(bench.railway.runRoute(2));
    ASSERT_TRUE(waitFor([&] { return finished.count() == 1; }));
    ASSERT_EQ(log.entries.size(), 4u);
    EXPECT_EQ(log.entries[0].address, 0x3000u);
    EXPECT_EQ(log.entries[0].output, 1);
    EXPECT_EQ(log.entries[3].address, 0x3000u);
    EXPECT_EQ(log.entries[3].output, 0);
    EXPECT_EQ(bench.railway.accessory(1)->position(), 0);
}

TEST_F(RouteRuns, ARouteThatRunsItselfIsRefusedBeforeAnythingIsSwitched) {
    SwitchLog log(bench);
    QSignalSpy problems(&bench.railway, &Railway::problem);
    EXPECT_FALSE(bench.railway.runRoute(3));
    ASSERT_EQ(problems.count(), 1);
    EXPECT_TRUE(problems.first().at(0).toString().contains("3 -> 4"))
        << problems.first().at(0).toString().toStdString();
    QTest::qWait(50);
    EXPECT_TRUE(log.entries.empty());
}

TEST_F(RouteRuns, ARunningRouteIsNotStartedTwice) {
    QSignalSpy finished(&bench.railway, &Railway::routeFinished);
    ASSERT_TRUE(bench.railway.runRoute(1));
    EXPECT_FALSE(bench.railway.runRoute(1));
    ASSERT_TRUE(waitFor([&] { return finished.count() == 1; }));
    EXPECT_TRUE(bench.railway.runRoute(1)) << "again once it ended";
    ASSERT_TRUE(waitFor([&] { return finished.count() == 2; }));
}

TEST_F(RouteRuns, AStepTheStationDoesNotConfirmStopsTheRoute) {
    QSignalSpy failed(&bench.railway, &Railway::routeFailed);
    QSignalSpy progressed(&bench.railway, &Railway::routeProgressed);
    ASSERT_TRUE(bench.railway.runRoute(1));
    ASSERT_TRUE(waitFor([&] { return progressed.count() == 1; }));
    bench.deaf = true; // the station stops hearing during the 0.3 s wait
    ASSERT_TRUE(waitFor([&] { return failed.count() == 1; }));
    EXPECT_TRUE(failed.first().at(1).toString().contains("step 2 of 3"))
        << failed.first().at(1).toString().toStdString();
    EXPECT_FALSE(bench.railway.route(1)->running());
}

// A lost connection ends the run at once: no step of it is sent when the station is back.
TEST_F(RouteRuns, ALostConnectionCancelsTheRouteAndNothingOfItIsSentLater) {
    QSignalSpy failed(&bench.railway, &Railway::routeFailed);
    QSignalSpy progressed(&bench.railway, &Railway::routeProgressed);
    ASSERT_TRUE(bench.railway.runRoute(1));
    ASSERT_TRUE(waitFor([&] { return progressed.count() == 1; }));
    bench.stationEnd.close(); // the station goes away during the 0.3 s wait
    ASSERT_EQ(failed.count(), 1) << "at once, not after the next step timed out";
    EXPECT_TRUE(failed.first().at(1).toString().startsWith("cancelled after 1 of 3 steps"))
        << failed.first().at(1).toString().toStdString();
    EXPECT_FALSE(bench.railway.route(1)->running());
    EXPECT_FALSE(bench.railway.isStateReported());
    int switchings = 0;
    QObject::connect(&bench.station, &sim::SimulatedStation::frameReceived, &bench.railway,
                     [&](const can::CanFrame& frame) {
                         const auto message = cs2::decode(frame);
                         switchings += message && std::holds_alternative<cs2::AccessorySwitch>(message->body);
                     });
    bench.stationEnd.open();
    ASSERT_TRUE(waitFor([&] { return bench.appEnd.state() == transport::Transport::State::Connected; }));
    QTest::qWait(500); // longer than the route's remaining waits
    EXPECT_EQ(switchings, 0) << "switchings arrived after the loss";
}

cs2config::RouteFile routes(const char* text) {
    cs2config::Diagnostics diagnostics;
    return cs2config::RouteFile::read(cs2config::Document::parse(text, diagnostics), diagnostics);
}

TEST(RoutePlan, AReferencingStepsWaitDelaysTheFirstStepOfTheRouteItRuns) {
    const RoutePlan plan = RoutePlan::of(routes(Routes), 2);
    ASSERT_TRUE(plan.valid()) << plan.error.toStdString();
    ASSERT_EQ(plan.actions.size(), 4u);
    EXPECT_EQ(plan.actions[0].delay, 100ms);
    EXPECT_EQ(plan.actions[0].route, 1);
    EXPECT_EQ(plan.actions[1].delay, 300ms);
    EXPECT_EQ(plan.actions[3].route, 2);
    EXPECT_EQ(plan.actions[3].delay, 0ms);
}

TEST(RoutePlan, ARouteIsSetWhileEveryAccessoryStandsWhereItLeavesIt) {
    const RoutePlan plan = RoutePlan::of(routes(Routes), 2); // route 1 (W1 1, S5 1, W2 2), then W1 back to 0
    EXPECT_EQ(plan.finalPositions(), (std::map<std::int64_t, int>{{1, 0}, {2, 2}, {5, 1}}))
        << "the last switching of W1 counts";
    std::map<std::int64_t, int> layout{{1, 0}, {2, 2}, {5, 1}};
    const auto positionOf = [&layout](std::int64_t accessory) -> std::optional<int> {
        const auto it = layout.find(accessory);
        return it == layout.end() ? std::nullopt : std::optional<int>(it->second);
    };
    EXPECT_TRUE(plan.standsIn(positionOf));
    layout[2] = 0; // someone threw W2
    EXPECT_FALSE(plan.standsIn(positionOf));
    layout.erase(2); // W2's position not known
    EXPECT_FALSE(plan.standsIn(positionOf));
    EXPECT_FALSE(RoutePlan::of(routes(Routes), 4).standsIn(positionOf))
        << "a route that cannot run is never set";
}

TEST(RoutePlan, AMissingRouteOrReferenceCannotRun) {
    EXPECT_FALSE(RoutePlan::of(routes(Routes), 9).valid());
    const RoutePlan cycle = RoutePlan::of(routes(Routes), 4);
    EXPECT_FALSE(cycle.valid());
    EXPECT_TRUE(cycle.actions.empty());
}

} // namespace
} // namespace stellwerk::model::test
