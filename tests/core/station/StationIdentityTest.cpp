// Document 1.2.4: our hash from our UID, and a new one when another sender uses it.

#include "station/StationIdentity.h"

#include "ScriptedStation.h"

#include <QSignalSpy>

namespace stellwerk::station::test {
namespace {

TEST(StationIdentity, HashIsUidHighXorLowWithBits7To9Set110) {
    // 0x4743 ^ 0xF5DA = 0xB299; bits 0-6 stay (0x19), bits 7-15 move up to 10-15 (0x9400), marker 0x0300.
    EXPECT_EQ(StationIdentity(0x4743F5DA).hash(), 0x9719);
    EXPECT_EQ(StationIdentity(0x4743F5DA).uid(), 0x4743F5DAu);
}

TEST(StationIdentity, RandomUidIsADeviceUidWithAMarkedHash) {
    const StationIdentity identity;
    EXPECT_GE(identity.uid(), 0x10000u);
    EXPECT_TRUE(cs2::hasCs2Marker(identity.hash()));
}

TEST(StationIdentity, StampWritesOurHashAndKeepsTheRest) {
    StationIdentity identity(0x4743F5DA);
    const CanFrame stamped = identity.stamp(frame(0x04, false, 0x0000, {0, 0, 0x40, 0x05, 0x01, 0xF4}));
    EXPECT_EQ(stamped, frame(0x04, false, 0x9719, {0, 0, 0x40, 0x05, 0x01, 0xF4}));
}

TEST(StationIdentity, ForeignCommandWithOurHashChoosesANewHash) {
    Bench bench;
    QSignalSpy changed(&bench.session, &StationSession::hashChanged);
    const std::uint16_t old = bench.session.identity().hash();
    bench.station.sendToApp({frame(0x04, false, old, {0, 0, 0x40, 0x06, 0x00, 0x64})});
    ASSERT_TRUE(waitFor([&] { return changed.count() == 1; }));
    const std::uint16_t fresh = bench.session.identity().hash();
    EXPECT_NE(fresh, old);
    EXPECT_TRUE(cs2::hasCs2Marker(fresh));
    EXPECT_EQ(changed.at(0).at(1).value<std::uint16_t>(), fresh);

    bench.session.ping();
    ASSERT_TRUE(waitFor([&] { return bench.station.count(cs2::Command::Ping) == 1; }));
    EXPECT_EQ(cs2::hash(bench.station.received.back()), fresh) << "we send with the new hash";
}

// A module of another protocol on a shared CAN bus sends an 11-bit frame whose id is our hash and whose
// payload looks like "system stop": it is counted as foreign and changes nothing.
TEST(StationIdentity, StandardFramesOfAnotherProtocolAreIgnored) {
    Bench bench;
    QSignalSpy changed(&bench.session, &StationSession::hashChanged);
    QSignalSpy updates(&bench.session, &StationSession::updated);
    const std::uint16_t own = bench.session.identity().hash();
    const std::uint8_t stopLike[5] = {};
    bench.station.sendToApp({can::CanFrame::standard(own & 0x7FF, stopLike)});
    ASSERT_TRUE(waitFor([&] { return bench.bus.received(busreading::Protocol::Foreign) == 1; }));
    EXPECT_EQ(bench.bus.received(busreading::Protocol::Cs2), 0u);
    EXPECT_EQ(bench.session.counters().frames, 0u) << "the session never saw it";
    EXPECT_EQ(bench.session.counters().undecodable, 0u);
    EXPECT_EQ(changed.count(), 0);
    EXPECT_EQ(updates.count(), 0) << "nothing reached the model";
    EXPECT_EQ(bench.session.identity().hash(), own);
}

TEST(StationIdentity, AnswersAndEchoesOfOurOwnFramesAreNoCollision) {
    Bench bench;
    QSignalSpy changed(&bench.session, &StationSession::hashChanged);
    const std::uint16_t own = bench.session.identity().hash();
    bench.station.silent = true;
    const CanFrame speed = frame(0x04, false, 0, {0, 0, 0x40, 0x06, 0x00, 0x64});
    bench.session.sendFrames({&speed, 1});
    bench.station.sendToApp({frame(0x04, false, own, {0, 0, 0x40, 0x06, 0x00, 0x64}),  // a gateway's echo
                             frame(0x04, true, own, {0, 0, 0x40, 0x06, 0x00, 0x64})}); // an answer
    ASSERT_TRUE(waitFor([&] { return bench.session.counters().frames == 2; }));
    EXPECT_EQ(changed.count(), 0);
    EXPECT_EQ(bench.session.identity().hash(), own);
}

} // namespace
} // namespace stellwerk::station::test
