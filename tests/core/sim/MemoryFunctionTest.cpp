// Chapter 9 on the simulated CS2: a memory function requested on the bus runs the route of its slot in
// fahrstrassen.cs2 (A1 = route 1, B1 = route 9, ... z8 = route 416), with the status answers the document
// describes (running, then activated; deactivated on release; a run error where no route can run).

#include "SimTestSupport.h"
#include "cs2/Automation.h"
#include "cs2config/AccessoryType.h"

#include <QElapsedTimer>
#include <QTest>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>

namespace stellwerk::sim::test {
namespace {

const char* const MemoryAccessories = R"([magnetartikel]
version
 .minor=1
artikel
 .id=1
 .name=W1
 .typ=rechtsweiche
 .stellung=0
 .dectyp=mm2
artikel
 .id=2
 .name=W2
 .typ=dreiwegweiche
 .stellung=0
 .dectyp=mm2
artikel
 .id=5
 .name=S5
 .typ=lichtsignal_HP01
 .stellung=0
 .dectyp=mm2
)";

// Route 1 (A1): W1 straight, S5 green. Route 9 (B1): W2 to its third position, then route 1. Route 10 (B2)
// runs itself. Route 11 (B3): W1 straight, after 0.2 s S5 green.
const char* const MemoryRoutes = R"([fahrstrassen]
version
 .minor=4
fahrstrasse
 .id=1
 .name=Einfahrt
 .item
 ..typ=mag
 ..magnetartikel=1
 ..stellung=1
 .item
 ..typ=mag
 ..magnetartikel=5
 ..stellung=1
fahrstrasse
 .id=9
 .name=Durchfahrt
 .item
 ..typ=mag
 ..magnetartikel=2
 ..stellung=2
 .item
 ..fsverweis=1
fahrstrasse
 .id=10
 .name=Kreis
 .item
 ..fsverweis=10
fahrstrasse
 .id=11
 .name=Langsam
 .item
 ..typ=mag
 ..magnetartikel=1
 ..stellung=1
 .item
 ..typ=mag
 ..magnetartikel=5
 ..stellung=1
 ..sekunde=0.2
)";

StationLayout memoryLayout() {
    return StationLayout::fromFiles({{"magnetartikel.cs2", MemoryAccessories},
                                     {"fahrstrassen.cs2", MemoryRoutes},
                                     {"gleisbild.cs2", trackPlan},
                                     {"gleisbilder/Bahnhof.cs2", stationPage}});
}

// The status values of the 0x30 answers in an emission, in order.
std::vector<int> statuses(const StationProbe& probe, const std::vector<CanFrame>& frames) {
    std::vector<int> values;
    for (const CanFrame& f : frames) {
        const cs2::Message message = probe.decoded(f);
        if (const auto* status = std::get_if<cs2::AutomationSwitch>(&message.body))
            values.push_back(status->position);
    }
    return values;
}

class MemoryFunctionTest : public ::testing::Test {
protected:
    StationProbe probe{StationProbe::defaultOptions(), memoryLayout()};
};

TEST_F(MemoryFunctionTest, RequestOfA1RunsRouteOneAndAnswersRunningThenActivated) {
    const auto answer = probe.send("00604711 6 00 00 41 31 01 00"); // master (broadcast), A1, activate
    ASSERT_EQ(answer.size(), 4u);
    EXPECT_EQ(answer.front(), probe.answer("00604711 6 00 00 41 31 02 00")); // running
    EXPECT_EQ(answer[1], probe.answer("00164711 6 00 00 30 00 01 01"));      // W1 straight
    EXPECT_EQ(answer[2], probe.answer("00164711 6 00 00 30 04 01 01"));      // S5 green
    EXPECT_EQ(answer.back(), probe.answer("00604711 6 00 00 41 31 01 00"));  // activated
    EXPECT_EQ(probe.station.accessoryPosition(0x3000), 1);
    EXPECT_EQ(probe.station.accessoryPosition(0x3004), 1);
}

TEST_F(MemoryFunctionTest, B1RunsRouteNineWithTheRouteItReferences) {
    const auto answer = probe.send("00604711 6 00 00 42 31 01 00");
    EXPECT_EQ(statuses(probe, answer), (std::vector<int>{2, 1}));
    // The three-way turnout's third position is output 0 of its second address (0x3002).
    EXPECT_EQ(probe.station.accessoryPosition(0x3002), 0);
    EXPECT_EQ(probe.station.accessoryPosition(0x3000), 1);
    EXPECT_EQ(probe.station.accessoryPosition(0x3004), 1);
}

TEST_F(MemoryFunctionTest, AStepsWaitIsKeptAndActivatedFollowsTheLastStep) {
    QElapsedTimer clock;
    clock.start();
    const auto first = probe.send("00604711 6 00 00 42 33 01 00"); // B3
    ASSERT_EQ(first.size(), 2u);
    EXPECT_EQ(first.front(), probe.answer("00604711 6 00 00 42 33 02 00")); // running
    EXPECT_EQ(first.back(), probe.answer("00164711 6 00 00 30 00 01 01"));  // W1 at once
    EXPECT_EQ(probe.station.accessoryPosition(0x3004), 0) << "S5 waits 0.2 s";
    const std::size_t before = probe.batches.size();
    ASSERT_TRUE(QTest::qWaitFor([&] { return probe.batches.size() > before; }, 3000));
    EXPECT_GE(clock.elapsed(), 180);
    const auto later = probe.batches.back();
    ASSERT_EQ(later.size(), 2u);
    EXPECT_EQ(later.front(), probe.answer("00164711 6 00 00 30 04 01 01")); // S5 green
    EXPECT_EQ(later.back(), probe.answer("00604711 6 00 00 42 33 01 00"));  // activated
    EXPECT_EQ(probe.station.accessoryPosition(0x3004), 1);
}

TEST_F(MemoryFunctionTest, TheStationsOwnDeviceIdRunsItToo) {
    // 2.13: the simulated master's device id is 1.
    EXPECT_EQ(statuses(probe, probe.send("00604711 6 00 01 41 31 01 00")), (std::vector<int>{2, 1}));
    EXPECT_EQ(probe.station.accessoryPosition(0x3004), 1);
}

TEST_F(MemoryFunctionTest, AnotherDevicesMemoryIsLeftToIt) {
    EXPECT_TRUE(probe.send("00604711 6 00 05 41 31 01 00").empty());
    EXPECT_EQ(probe.station.accessoryPosition(0x3004), 0);
}

TEST_F(MemoryFunctionTest, ReleaseAnswersDeactivatedAndSwitchesNothing) {
    const auto answer = probe.send("00604711 6 00 00 41 31 00 00");
    ASSERT_EQ(answer.size(), 1u);
    EXPECT_EQ(answer.front(), probe.answer("00604711 6 00 00 41 31 00 00"));
    EXPECT_EQ(probe.station.accessoryPosition(0x3000), 0);
}

TEST_F(MemoryFunctionTest, SlotWithoutRouteOrARouteRunningItselfIsARunError) {
    EXPECT_EQ(statuses(probe, probe.send("00604711 6 00 00 41 35 01 00")), (std::vector<int>{255}));    // A5
    EXPECT_EQ(statuses(probe, probe.send("00604711 6 00 00 42 32 01 00")), (std::vector<int>{2, 255})); // B2
    EXPECT_EQ(statuses(probe, probe.send("00604711 6 00 00 41 39 01 00")), (std::vector<int>{255})); // "A9"
}

TEST_F(MemoryFunctionTest, AStatusAnswerOfAnotherDeviceIsNoCommand) {
    EXPECT_TRUE(probe.send("00614711 6 00 00 41 31 01 00").empty());
    EXPECT_EQ(probe.station.accessoryPosition(0x3000), 0);
}

std::string readCorpus(std::string_view relative) {
    const auto path = std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus" / relative;
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in.good()) << "corpus file missing: " << path;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// TrainControl's real station: route 2 ("A2") switches each of its accessories to the route's position.
TEST(MemoryFunctionCorpus, A2RunsRouteTwoOfARealFahrstrassenFile) {
    const std::string accessories = readCorpus("bob123456678__TrainControl/test/magnetartikel.cs2");
    const std::string routes = readCorpus("bob123456678__TrainControl/test/fahrstrassen.cs2");
    StationProbe probe(StationProbe::defaultOptions(),
                       StationLayout::fromFiles({{"magnetartikel.cs2", accessories},
                                                 {"fahrstrassen.cs2", routes},
                                                 {"gleisbild.cs2", trackPlan},
                                                 {"gleisbilder/Bahnhof.cs2", stationPage}}));
    const cs2config::Route* route = probe.station.layout().routes().find(2);
    ASSERT_NE(route, nullptr);
    ASSERT_GE(route->steps.size(), 5u);
    const auto answer = probe.send("00604711 6 00 00 41 32 01 00");
    EXPECT_EQ(statuses(probe, answer), (std::vector<int>{2, 1}));
    // Every single-address article stands where the route's last step for it left it.
    std::map<std::uint32_t, int> expected;
    for (const cs2config::RouteStep& step : route->steps)
        for (const cs2config::Accessory& a : probe.station.layout().accessories().accessories)
            if (a.id == step.accessory && cs2config::findAccessoryType(a.type) &&
                cs2config::findAccessoryType(a.type)->addresses == 1)
                expected[(a.protocol == "dcc" ? 0x3800u : 0x3000u) + std::uint32_t(a.id) - 1] =
                    int(step.position);
    ASSERT_GE(expected.size(), 3u);
    for (const auto& [locId, position] : expected)
        EXPECT_EQ(probe.station.accessoryPosition(locId), position) << std::hex << locId;
}

} // namespace
} // namespace stellwerk::sim::test
