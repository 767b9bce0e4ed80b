// The RO module session against a simulated module over a real loopback transport (notes B3.3): relays
// switched once and reported only when the module confirmed them, inputs polled with their change flags,
// and faults: lost requests and answers, late answers, duplicate job ids, invalid commands.
#include "RoRig.h"

#include <gtest/gtest.h>

namespace stellwerk::romodule::test {
namespace {

using Relays = std::vector<std::uint32_t>;

TEST(RoModuleSession, StartReadsTheRelaysIntoTheShadow) {
    RoRig rig;
    rig.module.presetRelays(0x0005);
    ASSERT_TRUE(rig.started());
    EXPECT_EQ(rig.session->state(), RoModuleSession::State::Online);
    EXPECT_EQ(rig.session->outputs(), 0x0005u);
    EXPECT_EQ(rig.session->inputs(), 0u);
    EXPECT_TRUE(rig.relayWrites().empty()) << "reading the relays switches nothing";
}

// 004 §3.4: relay 14 on is the word 0x2000 at 0x0000; the others keep what the shadow says.
TEST(RoModuleSession, Section3_4_SwitchingRelay14WritesTheWordOnce) {
    RoRig rig;
    rig.module.presetRelays(0x0001);
    ASSERT_TRUE(rig.started());
    ASSERT_TRUE(rig.session->setOutput(14, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0x2001u; }));
    EXPECT_EQ(rig.relayWrites(), Relays{0x2001});
    EXPECT_TRUE(rig.module.relay(14));
    EXPECT_EQ(rig.module.writes().front().width, ro::Width::Word);
    EXPECT_FALSE(rig.session->setOutput(17, true)) << "the profile has 16 relays";
}

TEST(RoModuleSession, ChangesAskedTogetherGoInOneOrTwoWritesAndAllOffClearsThem) {
    RoRig rig;
    ASSERT_TRUE(rig.started());
    for (int relay = 1; relay <= 4; ++relay)
        ASSERT_TRUE(rig.session->setOutput(relay, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0x000Fu && rig.session->idle(); }));
    EXPECT_EQ(rig.relayWrites().size(), 2u) << "relay 1 at once, 2-4 together when it is confirmed";
    EXPECT_EQ(rig.relayWrites().back(), 0x000Fu);
    ASSERT_TRUE(rig.session->switchAllOff());
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0u; }));
    EXPECT_EQ(rig.module.relays(), 0u);
}

TEST(RoModuleSession, InputsArePolledWithTheirChangeFlags) {
    SessionTiming timing = RoRig::quickTiming();
    timing.pollPeriod = std::chrono::milliseconds(50);
    RoRig rig(timing);
    ASSERT_TRUE(rig.started());
    rig.module.setInput(3, true);
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->inputs() == 0x0004u; }));
    EXPECT_EQ(rig.changedSeen, 0x0004u);
    // On and off again between two polls: the input reads off, its change flag tells it moved.
    rig.changedSeen = 0;
    rig.module.setInput(5, true);
    rig.module.setInput(5, false);
    ASSERT_TRUE(rig.waitFor([&] { return rig.changedSeen == 0x0010u; }));
    EXPECT_EQ(rig.session->inputs(), 0x0004u);
    EXPECT_EQ(rig.module.registers().read(0x0022, ro::Width::Word), 0u) << "read-to-clear (004 §2.1)";
}

// The request never reaches the module: the same job id again after the timeout, carried out once.
TEST(RoModuleSession, ALostRequestIsSentAgainAndCarriedOutOnce) {
    RoRig rig;
    ASSERT_TRUE(rig.started());
    rig.module.loseRequests(1);
    ASSERT_TRUE(rig.session->setOutput(2, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0x0002u; }));
    EXPECT_EQ(rig.relayWrites(), Relays{0x0002});
    EXPECT_EQ(rig.session->counters().timeouts, 1u);
    EXPECT_EQ(rig.session->counters().duplicates, 0u);
}

// The module switched but its answer was lost: the resend earns 0xFD, which confirms the write.
TEST(RoModuleSession, ALostAnswerIsConfirmedByTheDuplicateJobIdNotSwitchedTwice) {
    RoRig rig;
    ASSERT_TRUE(rig.started());
    rig.module.loseAnswers(1);
    ASSERT_TRUE(rig.session->setOutput(2, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0x0002u; }));
    EXPECT_EQ(rig.relayWrites(), Relays{0x0002}) << "switched once";
    EXPECT_EQ(rig.session->counters().duplicates, 1u);
    EXPECT_EQ(rig.failed, 0u);
}

// An answer later than the timeout: the resend meets 0xFD, the late OK ends the request, the 0xFD that
// follows is stale.
TEST(RoModuleSession, ALateAnswerEndsTheRequestOnce) {
    RoRig rig;
    ASSERT_TRUE(rig.started());
    rig.module.setAnswerDelay(std::chrono::milliseconds(150));
    ASSERT_TRUE(rig.session->setOutput(7, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0x0040u; }));
    rig.module.setAnswerDelay(std::chrono::milliseconds(0));
    ASSERT_TRUE(rig.session->setOutput(8, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0x00C0u && rig.session->idle(); }));
    EXPECT_EQ(rig.relayWrites(), (Relays{0x0040, 0x00C0}));
    EXPECT_TRUE(rig.waitFor([&] {
        return rig.session->counters().stale + rig.session->counters().unsolicited >= 1;
    })) << "the 0xFD to the resend comes late too, and is taken for no one's";
    EXPECT_EQ(rig.relayWrites(), (Relays{0x0040, 0x00C0}));
}

// The module still remembers our first job id (another master, or our previous run): a fresh one.
TEST(RoModuleSession, ADuplicateJobIdOnTheFirstSendTakesAFreshOne) {
    RoRig rig;
    ASSERT_TRUE(rig.started());
    const std::uint8_t remembered = rig.session->nextJob();
    rig.module.rememberJob(remembered);
    ASSERT_TRUE(rig.session->setOutput(16, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0x8000u; }));
    ASSERT_EQ(rig.module.writes().size(), 1u);
    EXPECT_NE(rig.module.writes().front().job, remembered);
    EXPECT_EQ(rig.session->counters().duplicates, 1u);
}

// 004 §3.5.2.2: 0xFE has no job id and ends the one request in flight; it is not retried.
TEST(RoModuleSession, AnInvalidCommandEndsTheRequestWithoutRetry) {
    RoRig rig;
    ASSERT_TRUE(rig.started());
    std::optional<ro::Outcome> outcome;
    QObject::connect(rig.session.get(), &RoModuleSession::requestFinished, rig.session.get(),
                     [&](RoModuleSession::RequestId, const ro::Outcome& o) { outcome = o; });
    const std::uint64_t before = rig.module.requestsSeen();
    rig.session->read(0xFFFE, ro::Width::Long); // runs past 0xFFFF: the simulator refuses it (notes R13)
    ASSERT_TRUE(rig.waitFor([&] { return outcome.has_value(); }));
    EXPECT_EQ(outcome->kind, ro::Outcome::Kind::InvalidCommand);
    EXPECT_EQ(rig.module.requestsSeen(), before + 1);
    EXPECT_EQ(rig.session->counters().invalid, 1u);
    EXPECT_EQ(rig.session->state(), RoModuleSession::State::Online);
}

TEST(RoModuleSession, RegisterReadsAndWritesOfTheExplorer) {
    RoRig rig;
    ASSERT_TRUE(rig.started());
    std::vector<ro::Outcome> outcomes;
    QObject::connect(rig.session.get(), &RoModuleSession::requestFinished, rig.session.get(),
                     [&](RoModuleSession::RequestId, const ro::Outcome& o) { outcomes.push_back(o); });
    rig.session->write(0x0012, ro::Width::Byte, 0x0F); // 004 §3.3
    rig.session->read(0x0012, ro::Width::Byte);
    ASSERT_TRUE(rig.waitFor([&] { return outcomes.size() == 2; }));
    EXPECT_TRUE(outcomes[0].succeeded());
    EXPECT_EQ(outcomes[1].value, 0x0Fu);
    EXPECT_EQ(rig.module.registers().byteAt(0x0012), 0x0F);
}

TEST(RoModuleSession, ElevenBitModulesAreRefusedOnANetworkGatewayOnly) {
    ro::RoProfile profile = ro::RoProfile::simulator(1);
    profile.ids = {0x700, 0x701, false};
    RoRig rig(RoRig::quickTiming(), profile);
    EXPECT_EQ(rig.session->problem(), "") << "a loopback carries 11-bit frames";
    ASSERT_TRUE(rig.started());
    ASSERT_TRUE(rig.session->setOutput(1, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 1u; }));
}

} // namespace
} // namespace stellwerk::romodule::test
