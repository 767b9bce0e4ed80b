// Document 1.2.5: a command without acknowledgement must be assumed not carried out. A throttle marks the
// control whose command the station did not acknowledge; the railway says which control that was.

#include "ModelBench.h"
#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/LocomotiveFile.h"

namespace stellwerk::model::test {
namespace {

using Control = Railway::LocomotiveControl;

TEST(LocomotiveCommands, AnAcknowledgedSpeedIsAnnouncedAsSentThenAcknowledged) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    QSignalSpy sent(&bench.railway, &Railway::locomotiveCommandSent);
    QSignalSpy acknowledged(&bench.railway, &Railway::locomotiveCommandAcknowledged);
    QSignalSpy failed(&bench.railway, &Railway::locomotiveCommandFailed);
    bench.railway.setSpeed(Br86, 300);
    ASSERT_EQ(sent.count(), 1);
    EXPECT_EQ(sent.first().at(0).toUInt(), Br86);
    EXPECT_EQ(sent.first().at(1).value<Control>(), Control::Speed);
    EXPECT_EQ(acknowledged.count(), 0) << "not before the station answered";
    ASSERT_TRUE(waitFor([&] { return acknowledged.count() == 1; }));
    EXPECT_EQ(acknowledged.first().at(0).toUInt(), Br86);
    EXPECT_EQ(acknowledged.first().at(1).value<Control>(), Control::Speed);
    EXPECT_EQ(bench.railway.locomotive(Br86)->speed(), 300);
    EXPECT_EQ(failed.count(), 0);
}

TEST(LocomotiveCommands, AFunctionCommandNamesItsFunction) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    QSignalSpy acknowledged(&bench.railway, &Railway::locomotiveCommandAcknowledged);
    bench.railway.setFunction(Br86, 1, true);
    ASSERT_TRUE(waitFor([&] { return acknowledged.count() == 1; }));
    EXPECT_EQ(acknowledged.first().at(1).value<Control>(), Control::Function);
    EXPECT_EQ(acknowledged.first().at(2).toInt(), 1);
    EXPECT_TRUE(bench.railway.locomotive(Br86)->functionOn(1));
}

TEST(LocomotiveCommands, ADirectionIsAcknowledgedAfterTheLocomotiveShowsIt) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    cs2::Direction seen = cs2::Direction::Forward;
    QObject::connect(&bench.railway, &Railway::locomotiveCommandAcknowledged, &bench.railway,
                     [&](quint32 loco) { seen = bench.railway.locomotive(loco)->direction(); });
    bench.railway.setDirection(Br86, cs2::Direction::Backward);
    ASSERT_TRUE(waitFor([&] { return seen == cs2::Direction::Backward; }));
}

TEST(LocomotiveCommands, AnUnansweredCommandFailsWithTheReasonForItsControl) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    QSignalSpy failed(&bench.railway, &Railway::locomotiveCommandFailed);
    QSignalSpy acknowledged(&bench.railway, &Railway::locomotiveCommandAcknowledged);
    bench.deaf = true;
    bench.railway.setFunction(Br86, 0, true);
    ASSERT_TRUE(waitFor([&] { return failed.count() == 1; }));
    EXPECT_EQ(failed.first().at(0).toUInt(), Br86);
    EXPECT_EQ(failed.first().at(1).value<Control>(), Control::Function);
    EXPECT_EQ(failed.first().at(2).toInt(), 0);
    EXPECT_TRUE(failed.first().at(3).toString().startsWith("no answer from the station"))
        << failed.first().at(3).toString().toStdString();
    EXPECT_EQ(acknowledged.count(), 0);
    EXPECT_FALSE(bench.railway.locomotive(Br86)->functionOn(0));
}

// Document 2.4: an emergency stop stops the locomotive at once; the station does not announce speed 0.
TEST(LocomotiveCommands, AnEmergencyStopIsAnnouncedAndLeavesTheLocomotiveStanding) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    bench.railway.setSpeed(Br86, 600);
    ASSERT_TRUE(waitFor([&] { return bench.railway.locomotive(Br86)->speed() == 600; }));
    QSignalSpy acknowledged(&bench.railway, &Railway::locomotiveCommandAcknowledged);
    bench.railway.emergencyStop(Br86);
    ASSERT_TRUE(waitFor([&] { return acknowledged.count() == 1; }));
    EXPECT_EQ(acknowledged.first().at(0).toUInt(), Br86);
    EXPECT_EQ(acknowledged.first().at(1).value<Control>(), Control::EmergencyStop);
    EXPECT_EQ(bench.railway.locomotive(Br86)->speed(), 0);
    EXPECT_EQ(bench.station.loco(Br86)->speed, 0);
}

// Chapter 8.1.3: `.tachomax` is the speedometer's full scale; `..typ` the function icon; a CS2 marks a
// momentary key by adding 128 to the icon number when it writes no `..dauer`.
TEST(LocomotiveFromFile, KeepsAddressTachoIconAndHowEachFunctionTriggers) {
    const char* const text = R"([lokomotive]
lokomotive
 .name=BR 01
 .uid=0x4007
 .adresse=0x7
 .typ=mfx
 .icon=BR 01 DB
 .tachomax=160
 .funktionen
 ..nr=0
 ..typ=1
 .funktionen
 ..nr=2
 ..typ=138
 .funktionen
 ..nr=3
 ..typ=138
 ..dauer=2
 .funktionen
 ..nr=4
 ..typ=10
 ..dauer=-1
)";
    cs2config::Diagnostics diagnostics;
    const auto file =
        cs2config::LocomotiveFile::read(cs2config::Document::parse(text, diagnostics), diagnostics);
    ASSERT_EQ(file.locomotives.size(), 1U);
    const Locomotive loco = Locomotive::fromFile(file.locomotives.front());
    EXPECT_EQ(loco.address(), 7U);
    EXPECT_EQ(loco.protocol(), cs2::Protocol::Mfx);
    EXPECT_EQ(loco.tachoMax(), 160);
    EXPECT_EQ(loco.iconName(), QStringLiteral("BR 01 DB"));
    using Trigger = cs2config::FunctionTrigger;
    EXPECT_EQ(loco.function(0)->trigger, Trigger::Latching);
    EXPECT_EQ(loco.function(2)->trigger, Trigger::Momentary);
    EXPECT_EQ(loco.function(2)->icon, 138);
    EXPECT_EQ(loco.function(3)->trigger, Trigger::Timed);
    EXPECT_EQ(loco.function(3)->duration, 2);
    EXPECT_EQ(loco.function(4)->trigger, Trigger::Momentary);
}

} // namespace
} // namespace stellwerk::model::test
