// A module that goes away and comes back (after 1 s and after 20 s, as the handheld fault tests do), and
// another program's frames on the same bus: nothing is switched twice, nothing reported switched that the
// module did not confirm, and the session finds the module again.
#include "RoRig.h"
#include "cs2/Codec.h"
#include "cs2/Request.h"

#include <QTimer>
#include <gtest/gtest.h>

namespace stellwerk::romodule::test {
namespace {

using Relays = std::vector<std::uint32_t>;

class RoModuleGoneAndBack : public ::testing::TestWithParam<int> {};

TEST_P(RoModuleGoneAndBack, NothingIsReportedSwitchedAndTheModuleIsFoundAgain) {
    const int outageMs = GetParam();
    SessionTiming timing = RoRig::quickTiming();
    timing.pollPeriod = std::chrono::milliseconds(250);
    RoRig rig(timing);
    rig.module.presetRelays(0x0001);
    ASSERT_TRUE(rig.started());
    std::vector<RoModuleSession::State> states;
    QObject::connect(rig.session.get(), &RoModuleSession::stateChanged, rig.session.get(),
                     [&](RoModuleSession::State state) { states.push_back(state); });

    rig.module.unplug();
    ASSERT_TRUE(rig.session->setOutput(2, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->state() == RoModuleSession::State::Offline; }));
    EXPECT_EQ(rig.failed, 0x0002u) << "the switch it could not confirm is reported as failed";
    EXPECT_NE(rig.session->outputs(), std::optional<std::uint32_t>(0x0003)) << "never shown as switched";
    EXPECT_FALSE(rig.session->setOutput(3, true)) << "refused while offline";

    support::runEventsUntil([] { return false; }, outageMs);
    EXPECT_EQ(rig.session->state(), RoModuleSession::State::Offline);
    rig.module.plugIn();
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->state() == RoModuleSession::State::Online; }));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs().has_value(); })) << "the relays read again";
    EXPECT_EQ(rig.session->outputs(), 0x0001u) << "relay 2 was never switched";
    EXPECT_TRUE(rig.relayWrites().empty());

    ASSERT_TRUE(rig.session->setOutput(2, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == 0x0003u; }));
    EXPECT_EQ(rig.relayWrites(), Relays{0x0003}) << "switched once, after it was back";
    EXPECT_EQ(states, (std::vector{RoModuleSession::State::Offline, RoModuleSession::State::Online}));
}

// 1 s: back within a few polls. 20 s: after many polls in vain.
INSTANTIATE_TEST_SUITE_P(BackAfter, RoModuleGoneAndBack, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });

// The module switches, its answer is lost and it goes away at once: Stellwerk cannot know, so it reports
// the change as failed (never as done); when the module is back the relays are read, and show the truth.
TEST(RoModuleGoneAndBackAfterSwitching, TheRelaysAreReadAgainAndShowWhatTheModuleDid) {
    SessionTiming timing = RoRig::quickTiming();
    timing.pollPeriod = std::chrono::milliseconds(250);
    RoRig rig(timing);
    ASSERT_TRUE(rig.started());
    rig.module.loseAnswers(1);
    QObject::connect(&rig.module, &sim::SimulatedRoModule::relaysChanged, &rig.module,
                     [&] { rig.module.unplug(); });
    ASSERT_TRUE(rig.session->setOutput(5, true));
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->state() == RoModuleSession::State::Offline; }));
    EXPECT_EQ(rig.failed, 0x0010u);
    EXPECT_NE(rig.session->outputs(), std::optional<std::uint32_t>(0x0010)) << "not reported as switched";
    EXPECT_TRUE(rig.module.relay(5)) << "though the module did switch";

    support::runEventsUntil([] { return false; }, 1000);
    rig.module.plugIn();
    ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs().has_value(); }));
    EXPECT_EQ(rig.session->outputs(), 0x0010u) << "read again: now Stellwerk shows it";
    EXPECT_EQ(rig.relayWrites(), Relays{0x0010}) << "and it was not switched a second time";
}

// Another program on the bus: a CS2 talking, frames of another RO module, and another master that reads
// our module's inputs with its own job ids (so the module answers it on our answer id, and remembers its
// job ids). Our relay changes are each carried out once and reported only when confirmed.
class OtherProgram : public QObject {
    Q_OBJECT
public:
    explicit OtherProgram(const ro::RoProfile& module) : module_(module) {
        connect(&clock_, &QTimer::timeout, this, &OtherProgram::speak);
        clock_.start(7);
    }
    void receive(const can::CanFrame&) {}
    int spoken = 0;
signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);

private:
    void speak() {
        ++spoken;
        const ro::Request read{ro::Request::Kind::Read, ro::Width::Word, 0x0020, std::uint8_t(spoken * 37)};
        ro::RoProfile other = ro::RoProfile::simulator(2);
        emit framesEmitted({cs2::encode(cs2::request(cs2::SystemGo{0})), module_.requestFrame(read),
                            other.requestFrame(read),
                            other.answerFrame(ro::OkAnswer{ro::Width::Word, 1, 2})});
    }
    ro::RoProfile module_;
    QTimer clock_;
};

TEST(RoModuleSharedBus, AnotherProgramsFramesNeitherSwitchTwiceNorFakeAConfirmation) {
    RoRig rig;
    ASSERT_TRUE(rig.started());
    OtherProgram other(rig.profile);
    rig.simulatedBus.attach(other);
    std::uint32_t expected = 0;
    for (int relay = 1; relay <= 8; ++relay) {
        expected |= 1u << (relay - 1);
        ASSERT_TRUE(rig.session->setOutput(relay, true));
        ASSERT_TRUE(rig.waitFor([&] { return rig.session->outputs() == expected || rig.failed; }))
            << "relay " << relay;
        const int spoken = other.spoken;
        ASSERT_TRUE(rig.waitFor([&] { return other.spoken >= spoken + 3; })); // the other one talks meanwhile
    }
    EXPECT_EQ(rig.failed, 0u);
    EXPECT_GT(other.spoken, 5);
    EXPECT_EQ(rig.module.relays(), expected);
    const Relays writes = rig.relayWrites();
    EXPECT_EQ(writes.size(), 8u) << "each change carried out once";
    for (std::size_t i = 1; i < writes.size(); ++i)
        EXPECT_NE(writes[i], writes[i - 1]) << "no write repeated";
    EXPECT_GT(rig.session->counters().stale + rig.session->counters().unsolicited, 0u)
        << "the other master's answers reached the session and were not taken for ours";
}

} // namespace
} // namespace stellwerk::romodule::test

#include "RoModuleFaultsTest.moc"
