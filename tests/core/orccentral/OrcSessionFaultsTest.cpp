// The OpenRailCAN central under faults: a device that goes away and comes back after 1 s and after 20 s
// (real time: the project's e2e tests wait the same way), garbage frames and another program's frames on
// the bus. What reached the wire is asserted.

#include "OrcRig.h"

#include <QSignalSpy>
#include <QTest>

namespace stellwerk::orccentral::test {
namespace {

using namespace std::chrono_literals;

class DeviceGoneAndBack : public ::testing::TestWithParam<int> {};

// The twin (its bus id was reassigned to 0x2E02) is pulled out: missed pings make it offline. Powered up
// again it asks for 0x2E01 once more; the central gives it 0x2E02 again and it switches there, once.
TEST_P(DeviceGoneAndBack, OfflineAfterMissedPingsAndReassignedWhenBack) {
    const int outageMs = GetParam();
    OrcRig rig(fastSettings(200ms));
    sim::SimulatedOrcDecoder twin(TwinUid);
    rig.simBus.attach(twin);
    ASSERT_TRUE(rig.started({&twin}));
    sim::SimulatedOrcDecoder& moved = rig.decoder.busId() == 0x2E02 ? rig.decoder : twin;
    ASSERT_EQ(moved.busId(), 0x2E02);

    moved.unplug();
    ASSERT_TRUE(waitFor([&] { return rig.state(moved.uid()) == OrcDevice::State::Offline; }));
    EXPECT_EQ(rig.onlineCount(), 3u) << "the others stay online";
    QTest::qWait(outageMs);
    EXPECT_EQ(rig.state(moved.uid()), OrcDevice::State::Offline);

    moved.plugIn();
    ASSERT_EQ(moved.busId(), 0x2E01) << "powered up, it asks for the low 16 bits again";
    ASSERT_TRUE(waitFor([&] { return rig.state(moved.uid()) == OrcDevice::State::Online; }));
    EXPECT_EQ(moved.busId(), 0x2E02);
    EXPECT_EQ(rig.session.device(moved.uid())->busId, 0x2E02);

    rig.session.switchOutputs(0x2E02, 0x0F);
    ASSERT_TRUE(waitFor([&] { return moved.outputs() == 0x0F; }));
    QTest::qWait(300);
    EXPECT_EQ(rig.onWire("11100000 4 03 2E 02 0F"), 1u);
    EXPECT_EQ(moved.switchCount(), 1);
    EXPECT_EQ((&moved == &twin ? rig.decoder : twin).switchCount(), 0)
        << "the other decoder was not switched";
}

INSTANTIATE_TEST_SUITE_P(BackAfter, DeviceGoneAndBack, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });

// Garbage (malformed ORC frames, a DLC above 8 is dropped by the transport) and another program's frames
// (CS2 commands, an ORC throttle switching a turnout, a ping for a UID nobody has, a stray ack): nothing
// goes on the wire from the central, no device changes, and only the malformed ORC frames are counted.
TEST(OtherFramesOnTheBus, GarbageAndOtherProgramsAreIgnored) {
    OrcRig rig;
    ASSERT_TRUE(rig.started());
    ASSERT_TRUE(waitFor([&] { return rig.session.device(EncoderUid)->inputCount == 32; }));
    QSignalSpy changed(&rig.session, &OrcSession::deviceChanged);
    QSignalSpy reported(&rig.session, &OrcSession::switchReported);
    const std::vector<std::string> others = {
        "11100000 3 03 30 05",          // malformed: dekoder schalten without Pos
        "09000000 2 00 2E",             // malformed: Alles Aus with DLC 2
        "00084711 6 00 00 C0 03 01 20", // CS2 loco speed
        "00304711 0",                   // CS2 ping
        "11100077 4 03 30 05 01",       // another throttle switches MM2 turnout 5
        "19200077 5 00 12 34 56 78",    // another central pings a UID nobody has
        "11112E01 4 03 2E 01 07",       // an ack for a switch the central never sent
    };
    const std::size_t before = rig.wire.size();
    for (const std::string& frame : others)
        rig.fromOtherProgram(frame);
    ASSERT_TRUE(waitFor([&] { return rig.session.unreadableFrames() == 2; }));
    QTest::qWait(400);
    EXPECT_EQ(rig.wire.size(), before) << "the central said nothing";
    EXPECT_EQ(changed.count(), 0);
    EXPECT_EQ(reported.count(), 0);
    EXPECT_EQ(rig.onlineCount(), 3u);
    EXPECT_EQ(rig.decoder.switchCount(), 0) << "the other throttle switched 0x3005, not the CAN decoder";
    EXPECT_EQ(rig.bus.received(busreading::Protocol::Cs2), 2u);
}

} // namespace
} // namespace stellwerk::orccentral::test
