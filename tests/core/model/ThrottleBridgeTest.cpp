// OpenRailCAN throttles drive the CS2's locomotives (issue 15): a simulated throttle on the device bus sends
// Lok Speed, Lok Funktion and Lok(s) Nothalt (001 §Lok Control, group 0x81) for a Ziel-Id; the central's
// ThrottleBridge turns them into the railway's loco commands, which the simulated CS2 behind its loopback
// transport receives, and answers the throttle's queries from the railway's loco state (notes O24). The
// assertions are what reached the station's side of the wire.

#include "DeviceBench.h"
#include "cs2/Codec.h"
#include "model/RailwayThrottles.h"

namespace stellwerk::model::test {
namespace {

constexpr std::uint32_t ThrottleUid = 0x3A2E0400;

// The loco commands the station heard, in order, as text: "speed 0x4006 500", "direction 0xc003 2",
// "function 0x4006 1 1", "stop", "estop 0x4006".
class StationLocoLog {
public:
    explicit StationLocoLog(ModelBench& bench) : bench_(bench) {
        QObject::connect(&bench.stationEnd, &transport::Transport::framesReceived, &context_,
                         [this](const std::vector<can::CanFrame>& frames) {
                             for (const auto& frame : frames)
                                 if (!bench_.deaf)
                                     note(frame);
                         });
    }
    std::vector<std::string> heard;
    bool has(const std::string& line) const { return std::ranges::count(heard, line) > 0; }

private:
    void note(const can::CanFrame& frame) {
        const auto message = cs2::decode(frame);
        if (!message || message->response)
            return;
        const auto hex = [](std::uint32_t v) { return QString::number(v, 16).prepend("0x").toStdString(); };
        if (const auto* s = std::get_if<cs2::LocoSpeed>(&message->body); s && s->speed)
            heard.push_back("speed " + hex(s->loco.value()) + " " + std::to_string(*s->speed));
        else if (const auto* d = std::get_if<cs2::LocoDirection>(&message->body); d && d->direction)
            heard.push_back("direction " + hex(d->loco.value()) + " " + std::to_string(*d->direction));
        else if (const auto* f = std::get_if<cs2::LocoFunction>(&message->body); f && f->value)
            heard.push_back("function " + hex(f->loco.value()) + " " + std::to_string(f->function) + " " +
                            std::to_string(*f->value));
        else if (std::holds_alternative<cs2::SystemStop>(message->body))
            heard.push_back("stop");
        else if (const auto* e = std::get_if<cs2::LocoEmergencyStop>(&message->body))
            heard.push_back("estop " + hex(e->loco.value()));
    }

    ModelBench& bench_;
    QObject context_;
};

class ThrottleBridgeTest : public ::testing::Test {
protected:
    void SetUp() override {
        bench.simulatedBus.attach(throttle);
        throttle.plugIn();
        ASSERT_TRUE(bench.start());
        throttles.setSession(bench.orc.get());
        ASSERT_TRUE(waitFor([&] { return throttles.loco(Br86) && throttles.loco(V100); }));
    }
    Railway& railway() { return bench.railway.railway; }

    DeviceBench bench;
    sim::SimulatedOrcThrottle throttle{ThrottleUid};
    RailwayThrottles throttles{bench.railway.railway};
    StationLocoLog station{bench.railway};
};

// Lok Speed (0x81/0x01, D=0) for mfx Ziel-Id 0x4006: the CS2's mfx Loc-ID 0x4006, at the same speed.
TEST_F(ThrottleBridgeTest, LokSpeedDrivesTheMfxLocoAtTheStation) {
    throttle.drive(0x4006, 500);
    ASSERT_TRUE(waitFor([&] { return railway().locomotive(Br86)->speed() == 500; }));
    EXPECT_EQ(station.heard, std::vector<std::string>{"speed 0x4006 500"}) << "no direction: it runs forward";
}

// Bit 15 (reverse, notes O13) for DCC Ziel-Id 0xC003: the direction first, then the speed.
TEST_F(ThrottleBridgeTest, TheReverseBitTurnsTheDccLocoBeforeItsSpeed) {
    throttle.drive(0xC003, 300, false);
    ASSERT_TRUE(waitFor([&] { return station.heard.size() == 2; }));
    EXPECT_EQ(station.heard, (std::vector<std::string>{"direction 0xc003 2", "speed 0xc003 300"}));
}

// Lok Funktion Schalten one (0x81/0x04) and all 32 (0x81/0x03): only the functions that change are sent.
TEST_F(ThrottleBridgeTest, LokFunktionSwitchesOneFunctionOrTheOnesThatDiffer) {
    throttle.setFunction(0x4006, 1, true);
    ASSERT_TRUE(waitFor([&] { return railway().locomotive(Br86)->functionOn(1); }));
    EXPECT_EQ(station.heard, std::vector<std::string>{"function 0x4006 1 1"});
    throttle.setFunctions(0x4006, 0x00000001); // F0 on, F1 off
    ASSERT_TRUE(waitFor([&] { return station.heard.size() == 3; }));
    EXPECT_EQ(station.heard[1], "function 0x4006 0 1");
    EXPECT_EQ(station.heard[2], "function 0x4006 1 0");
}

// Lok Speed and Lok Funktion queries (D=0, DLC 3): the central answers with D=1 from the railway's state.
TEST_F(ThrottleBridgeTest, QueriesAreAnsweredFromTheStationsLocoState) {
    throttle.drive(0xC003, 250, false);
    throttle.setFunction(0xC003, 2, true);
    ASSERT_TRUE(waitFor([&] {
        const Locomotive* loco = railway().locomotive(V100);
        return loco->speed() == 250 && loco->functionOn(2);
    }));
    throttle.querySpeed(0xC003);
    throttle.queryFunctions(0xC003);
    ASSERT_TRUE(
        waitFor([&] { return throttle.answeredSpeed(0xC003) && throttle.answeredFunctions(0xC003); }));
    EXPECT_EQ(*throttle.answeredSpeed(0xC003), 0x8000 | 250) << "bit 15: reverse";
    EXPECT_EQ(*throttle.answeredFunctions(0xC003), 0x00000004u);
}

// MM2 turnout 5 (0x3005), MM loco 0 and the blank range 0x0100-0x2FFF are no CS2 locomotives: refused,
// counted, and nothing reaches the station; a query for them is not answered.
TEST_F(ThrottleBridgeTest, ZielIdsOutsideTheLocoRangesAreRefusedAndCounted) {
    throttle.drive(0x3005, 100);
    throttle.drive(0x0000, 100);
    throttle.setFunction(0x2000, 0, true);
    throttle.querySpeed(0x0800); // SX1
    ASSERT_TRUE(waitFor([&] { return throttles.bridge()->refused() == 4; }));
    QTest::qWait(300);
    EXPECT_TRUE(station.heard.empty()) << station.heard.front();
    EXPECT_FALSE(throttle.answeredSpeed(0x0800));
}

// The central goes (its bus went away): nothing drives the railway any more; a new central brings a new
// bridge on its bus.
TEST_F(ThrottleBridgeTest, TheBridgeGoesWithItsCentral) {
    bench.orc.reset();
    EXPECT_EQ(throttles.bridge(), nullptr);
    throttle.drive(0x4006, 500);
    QTest::qWait(300);
    EXPECT_TRUE(station.heard.empty());
    bench.orc = std::make_unique<orccentral::OrcSession>(bench.deviceBus, DeviceBench::orcSettings());
    throttles.setSession(bench.orc.get());
    throttle.drive(0x4006, 400);
    ASSERT_TRUE(waitFor([&] { return station.has("speed 0x4006 400"); }));
    EXPECT_FALSE(station.has("speed 0x4006 500"));
}

TEST(ThrottleZielIds, MapToTheCs2LocIdsOfTheSameNumber) {
    EXPECT_EQ(orccentral::locIdOf(0x0048), 0x0048u) << "MM loco 72, the derived vector V6";
    EXPECT_EQ(orccentral::locIdOf(0x00FF), 0x00FFu);
    EXPECT_EQ(orccentral::locIdOf(0x4006), 0x4006u);
    EXPECT_EQ(orccentral::locIdOf(0xC003), 0xC003u);
    for (const std::uint16_t notALoco : {0x0000, 0x0100, 0x3005, 0x3800, 0x8000, 0xBFFF})
        EXPECT_FALSE(orccentral::locIdOf(notALoco)) << std::hex << notALoco;
}

// Lok(s) Nothalt for one Ziel-Id (DLC 3) is the CS2's loco emergency stop; for all (DLC 1, vector V4) its
// STOP.
TEST_F(ThrottleBridgeTest, LokNothaltStopsOneLocoOrEverything) {
    throttle.emergencyStop(0x4006);
    ASSERT_TRUE(waitFor([&] { return station.heard.size() == 1; }));
    EXPECT_EQ(station.heard[0], "estop 0x4006");
    throttle.emergencyStop();
    ASSERT_TRUE(waitFor([&] { return station.heard.size() == 2; }));
    EXPECT_EQ(station.heard[1], "stop");
}

// The station hears nothing for a while (gone, from the railway's side): the throttle's speed command fails
// and is never delivered when the station hears again; the next one and an e-stop go through.
void stationGoneFor(DeviceBench& bench, sim::SimulatedOrcThrottle& throttle, StationLocoLog& station,
                    std::chrono::milliseconds away) {
    QSignalSpy failed(&bench.railway.railway, &Railway::locomotiveCommandFailed);
    bench.railway.deaf = true;
    throttle.drive(0x4006, 777);
    ASSERT_TRUE(waitFor([&] { return failed.count() == 1; })) << "given up";
    QTest::qWait(int(away.count()));
    bench.railway.deaf = false;
    QTest::qWait(500); // longer than every retry would have taken
    EXPECT_FALSE(station.has("speed 0x4006 777")) << "a command given up on reached the station";
    throttle.drive(0x4006, 100);
    throttle.emergencyStop(0x4006);
    ASSERT_TRUE(waitFor([&] { return station.has("speed 0x4006 100") && station.has("estop 0x4006"); }));
    EXPECT_FALSE(station.has("speed 0x4006 777"));
}

TEST_F(ThrottleBridgeTest, ACommandGivenUpOnIsNotDeliveredWhenTheStationIsBackAfterOneSecond) {
    stationGoneFor(bench, throttle, station, 1s);
}

TEST_F(ThrottleBridgeTest, ACommandGivenUpOnIsNotDeliveredWhenTheStationIsBackAfterTwentySeconds) {
    stationGoneFor(bench, throttle, station, 20s);
}

// The station's end of the link is closed (the station is gone; the app's transport reconnects): the
// throttle's commands, which still reach the central on the device bus, fail at once and none is kept for
// the station's return.
TEST_F(ThrottleBridgeTest, CommandsWhileTheStationIsGoneAreNotKeptForItsReturn) {
    QSignalSpy failed(&railway(), &Railway::locomotiveCommandFailed);
    bench.railway.stationEnd.close();
    throttle.drive(0x4006, 555);
    throttle.setFunction(0x4006, 1, true);
    ASSERT_TRUE(waitFor([&] { return failed.count() >= 2; })) << "refused while the station is gone";
    QTest::qWait(1000);
    bench.railway.stationEnd.open();
    ASSERT_TRUE(
        waitFor([&] { return bench.railway.appEnd.state() == transport::Transport::State::Connected; }));
    QTest::qWait(500);
    EXPECT_TRUE(station.heard.empty()) << station.heard.front();
    throttle.drive(0x4006, 120);
    ASSERT_TRUE(waitFor([&] { return station.has("speed 0x4006 120"); })) << "and drives again";
    EXPECT_FALSE(station.has("speed 0x4006 555"));
}

} // namespace
} // namespace stellwerk::model::test
