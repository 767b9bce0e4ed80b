// The OpenRailCAN central against simulated devices over a loopback transport: finding devices and giving
// them bus ids (001 §Bus ID Vergabe with Stellwerk's extension, notes A3.2), dekoder schalten (§0x88, A3.3),
// enkoder Abfrage and Status (§0x89, A3.5), Alles Aus / EIN and Lok Nothalt (A3.4), Überlast (A3.6).

#include "OrcRig.h"

#include <QSignalSpy>
#include <QTest>

namespace stellwerk::orccentral::test {
namespace {

using SwitchResult = OrcSession::SwitchResult;

// §Bus ID Vergabe: Find (DB2-5 = 0, Stellwerk's payload) reaches the bus; each device answers under the low
// 16 bits of its UID, which are free, and is online there.
TEST(BusIdVergabe, FindBringsEveryDeviceOnlineUnderItsOwnBusId) {
    OrcRig rig;
    ASSERT_TRUE(rig.started());
    EXPECT_EQ(rig.onWire("19200000 5 01 00 00 00 00"), 1u);
    EXPECT_EQ(rig.session.device(BoosterUid)->busId, 0x0042);
    EXPECT_EQ(rig.session.device(DecoderUid)->busId, 0x2E01);
    EXPECT_EQ(rig.session.device(EncoderUid)->type, std::uint8_t(orc::DeviceType::CanEncoder));
    EXPECT_EQ(rig.session.device(DecoderUid)->version, 0x0102);
    EXPECT_EQ(std::ranges::count_if(rig.wire,
                                    [](const std::string& f) { return f.rfind("19200000 7 02", 0) == 0; }),
              0)
        << "nobody was reassigned";
}

// §Bus ID Vergabe: two UIDs with the same low 16 bits; the central "zählt einfach hoch" and tells the second
// its new id (extension), which it confirms from there.
TEST(BusIdVergabe, DuplicateLow16UidIsAssignedTheNextFreeBusId) {
    OrcRig rig;
    sim::SimulatedOrcDecoder twin(TwinUid);
    rig.simBus.attach(twin);
    ASSERT_TRUE(rig.started({&twin}));
    const std::uint16_t first = rig.session.device(DecoderUid)->busId;
    const std::uint16_t second = rig.session.device(TwinUid)->busId;
    EXPECT_EQ(std::min(first, second), 0x2E01);
    EXPECT_EQ(std::max(first, second), 0x2E02);
    EXPECT_EQ(rig.decoder.busId(), first);
    EXPECT_EQ(twin.busId(), second);
    const std::uint32_t moved = first == 0x2E02 ? DecoderUid : TwinUid;
    const std::string assign =
        moved == TwinUid ? "19200000 7 02 11 11 2E 01 2E 02" : "19200000 7 02 3A 2E 2E 01 2E 02";
    EXPECT_EQ(rig.onWire(assign), 1u);
}

// A reserved legacy id (MM2 turnout 5 = 0x3005) is never handed to a CAN device.
TEST(BusIdVergabe, ReservedLegacyIdIsSkipped) {
    OrcRig rig;
    sim::SimulatedOrcDecoder legacyClash(0x3A2E3005);
    rig.simBus.attach(legacyClash);
    ASSERT_TRUE(rig.started({&legacyClash}));
    EXPECT_EQ(rig.session.device(0x3A2E3005)->busId, 0x3006);
    EXPECT_EQ(legacyClash.busId(), 0x3006);
}

// §dekoder schalten with the optional acknowledgement: switched once, reported confirmed.
TEST(DekoderSchalten, SwitchIsConfirmedByTheDecodersAck) {
    OrcRig rig;
    ASSERT_TRUE(rig.started());
    QSignalSpy reported(&rig.session, &OrcSession::switchReported);
    rig.session.switchOutputs(0x2E01, 0b101);
    ASSERT_TRUE(waitFor([&] { return reported.count() == 1; }));
    EXPECT_EQ(reported.at(0).at(2).value<SwitchResult>(), SwitchResult::Confirmed);
    EXPECT_EQ(rig.decoder.outputs(), 0b101);
    EXPECT_EQ(rig.decoder.switchCount(), 1);
    EXPECT_EQ(rig.onWire("11100000 4 03 2E 01 05"), 1u) << "nothing switched twice";
}

// Without the optional ack the switch is "sent, unconfirmed" after the answer timeout, not an error.
TEST(DekoderSchalten, SwitchWithoutAckIsSentUnconfirmed) {
    OrcRig rig(fastSettings(), false);
    ASSERT_TRUE(rig.started());
    QSignalSpy reported(&rig.session, &OrcSession::switchReported);
    rig.session.switchOutputs(0x2E01, 0x80);
    ASSERT_TRUE(waitFor([&] { return reported.count() == 1; }));
    EXPECT_EQ(reported.at(0).at(2).value<SwitchResult>(), SwitchResult::SentUnconfirmed);
    EXPECT_EQ(rig.decoder.outputs(), 0x80);
    EXPECT_EQ(rig.onWire("11100000 4 03 2E 01 80"), 1u);
}

// Notes A3.5: an encoder that comes online is queried; its answer (D=1) and later events (D=0) arrive.
TEST(EnkoderStatus, QueryAfterConnectingAndEventsOnChange) {
    OrcRig rig;
    rig.encoder.setInput(31, true); // before it is plugged in: no frame, but its state
    QSignalSpy inputs(&rig.session, &OrcSession::inputsChanged);
    ASSERT_TRUE(rig.started());
    ASSERT_TRUE(waitFor([&] { return rig.session.device(EncoderUid)->inputCount == 32; }));
    EXPECT_EQ(rig.onWire("11120000 3 10 2E 10"), 1u);
    EXPECT_EQ(rig.session.device(EncoderUid)->inputs, 0x80000000u);
    rig.encoder.setInput(2, true);
    ASSERT_TRUE(waitFor([&] { return rig.session.device(EncoderUid)->inputs == 0x80000004u; }));
    const QList<QVariant> last = inputs.takeLast();
    EXPECT_EQ(last.at(0).value<std::uint16_t>(), 0x2E10);
    EXPECT_EQ(last.at(2).value<std::uint32_t>(), 0x4u) << "only input 2 changed";
}

// Notes A3.3: a query nobody answers is sent 1 + 2 times (an answer timeout each), then reported failed.
TEST(EnkoderAbfrage, UnansweredQueryIsRetriedTwiceThenFails) {
    OrcRig rig;
    ASSERT_TRUE(rig.started());
    ASSERT_TRUE(waitFor([&] { return rig.session.device(EncoderUid)->inputCount == 32; }));
    rig.encoder.unplug();
    const std::size_t before = rig.onWire("11120000 3 10 2E 10");
    QSignalSpy failed(&rig.session, &OrcSession::queryFailed);
    rig.session.queryEncoder(0x2E10);
    ASSERT_TRUE(waitFor([&] { return failed.count() == 1; }));
    EXPECT_EQ(rig.onWire("11120000 3 10 2E 10") - before, 3u);
}

// Notes A3.4: Alles EIN / Alles Aus and Lok Nothalt reach every device; the booster follows.
TEST(AllesAusAllesEin, PowerAndEmergencyStopReachTheBooster) {
    OrcRig rig;
    ASSERT_TRUE(rig.started());
    rig.session.setPower(true);
    ASSERT_TRUE(waitFor([&] { return rig.booster.powered(); }));
    EXPECT_EQ(rig.onWire("09000000 1 01"), 1u);
    rig.session.emergencyStop();
    ASSERT_TRUE(waitFor([&] { return rig.booster.emergencyStopped(); }));
    EXPECT_EQ(rig.onWire("09020000 1 00"), 1u);
    rig.session.setPower(false);
    ASSERT_TRUE(waitFor([&] { return !rig.booster.powered(); }));
    EXPECT_EQ(rig.onWire("09000000 1 00"), 1u);
}

// Notes A3.4: Alles Aus from another device (a throttle) is mirrored, not answered.
TEST(AllesAusAllesEin, PowerOffByAnotherDeviceIsMirrored) {
    OrcRig rig;
    ASSERT_TRUE(rig.started());
    ASSERT_TRUE(waitFor([&] { return rig.session.device(EncoderUid)->inputCount == 32; }));
    rig.session.setPower(true);
    ASSERT_TRUE(waitFor([&] { return rig.booster.powered(); }));
    QSignalSpy power(&rig.session, &OrcSession::powerChanged);
    QSignalSpy stopped(&rig.session, &OrcSession::emergencyStopped);
    const std::size_t wireBefore = rig.wire.size();
    rig.fromOtherProgram("09000077 1 00");
    rig.fromOtherProgram("09020077 1 00");
    ASSERT_TRUE(waitFor([&] { return power.count() == 1 && stopped.count() == 1; }));
    EXPECT_FALSE(rig.session.powerOn());
    EXPECT_TRUE(power.at(0).at(1).toBool()) << "by another device";
    EXPECT_TRUE(stopped.at(0).at(0).toBool());
    QTest::qWait(300);
    EXPECT_EQ(rig.wire.size(), wireBefore) << "the central does not answer them";
    EXPECT_FALSE(rig.booster.powered()) << "the booster heard the other device too";
    EXPECT_TRUE(rig.booster.emergencyStopped());
}

// Notes A3.6: Überlast from the booster is reported per port; type 0x00 clears it.
TEST(Ueberlast, BoosterOverloadIsReportedAndCleared) {
    OrcRig rig;
    ASSERT_TRUE(rig.started());
    QSignalSpy overload(&rig.session, &OrcSession::overloadChanged);
    rig.booster.injectOverload(2, 1);
    ASSERT_TRUE(waitFor([&] { return overload.count() == 1; }));
    EXPECT_EQ(overload.at(0).at(0).value<std::uint16_t>(), 0x0042);
    EXPECT_EQ(overload.at(0).at(1).value<std::uint8_t>(), 2);
    EXPECT_EQ(overload.at(0).at(2).value<std::uint8_t>(), 1);
    EXPECT_EQ(rig.session.device(BoosterUid)->overloads.at(2), 1);
    rig.booster.clearOverload(2);
    ASSERT_TRUE(waitFor([&] { return overload.count() == 2; }));
    EXPECT_TRUE(rig.session.device(BoosterUid)->overloads.empty());
}

} // namespace
} // namespace stellwerk::orccentral::test

namespace stellwerk::orccentral::test {
namespace {

// The document gives no timeouts; the defaults are the ones the user guide (openrailcan.md) lists.
TEST(Timeouts, DefaultsAreTheGuides) {
    const OrcSession::Timing timing;
    EXPECT_EQ(timing.pingPeriod, std::chrono::milliseconds(5000));
    EXPECT_EQ(timing.missedPingsOffline, 3);
    EXPECT_EQ(timing.answerTimeout, std::chrono::milliseconds(250));
    EXPECT_EQ(timing.queryRetries, 2);
    EXPECT_EQ(timing.assignTries, 3);
    EXPECT_EQ(OrcSession::Settings{}.busId, 0x0000);
}

} // namespace
} // namespace stellwerk::orccentral::test
