// The master's behaviour beyond the trace: many logins at once, locomotive owners, the railway driven and
// told, stop and go both ways, liveness, another master, bad input, stacks and names remembered.

#include "MasterFixture.h"

#include <QSignalSpy>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::mastertest;
using mcanhandhelds::HandheldEvent;
using mcanhandhelds::HandheldState;

namespace {

constexpr std::uint32_t Br218 = 0x4006;
constexpr std::uint32_t Koef = 0x0005;
constexpr std::uint16_t FirstLoco = 0x0009;
constexpr std::uint16_t SecondLoco = 0x000A;

void twoLocos(MasterOnTable& table) {
    table.railway.locos = {
        {Br218,
         "BR 218 Ost",
         mcanhandhelds::LocoKind::Diesel,
         mcanhandhelds::RailFormat::Mfx,
         {{0, false}, {1, false}, {2, true}}},
        {Koef, "Köf III", mcanhandhelds::LocoKind::Diesel, mcanhandhelds::RailFormat::Motorola, {{0, false}}},
    };
    table.master.setRailway(&table.railway);
}

template <class T>
std::vector<T> only(const std::vector<mcan::Message>& messages) {
    std::vector<T> found;
    for (const mcan::Message& message : messages)
        if (const auto* m = std::get_if<T>(&message))
            found.push_back(*m);
    return found;
}

const mcanhandhelds::Handheld* handheldOf(const mcanhandhelds::HandheldMaster& master, std::uint32_t uid) {
    static std::vector<mcanhandhelds::Handheld> list;
    list = master.handhelds();
    for (const auto& handheld : list)
        if (handheld.uid == uid)
            return &handheld;
    return nullptr;
}

} // namespace

TEST(HandheldMaster, ThirtyOneLoginsAtOnceEachGetTheirOwnMidAndNode) {
    MasterOnTable table;
    std::vector<std::uint8_t> mids;
    for (std::uint32_t n = 0; n < 32; ++n) { // stage 0 of 32 handhelds before any goes on
        const auto replies =
            only<mcan::LoginReply>(decoded(table.tell(mcan::LoginRequest{0, std::uint8_t(n), 0})));
        if (n < 31) {
            ASSERT_EQ(replies.size(), 1u) << n;
            mids.push_back(replies[0].mid);
        } else {
            EXPECT_TRUE(replies.empty()); // the 32nd waits for its next try
        }
    }
    EXPECT_EQ(std::set<std::uint8_t>(mids.begin(), mids.end()).size(), 31u);
    for (std::uint8_t stage = 1; stage < 4; ++stage)
        for (std::uint32_t n = 0; n < 31; ++n)
            ASSERT_EQ(only<mcan::LoginReply>(decoded(table.tell(mcan::LoginRequest{
                                                 stage, std::uint8_t(stage == 3 ? n : 0), mids[n]})))
                          .size(),
                      1u);
    std::set<std::uint8_t> nodes;
    for (std::uint32_t n = 0; n < 31; ++n) {
        const std::array<std::uint8_t, 8> uid{std::uint8_t(n), 0, 0, std::uint8_t(n), 0, 2, 0, 3};
        table.tell(mcan::LoginDetails{4, mids[n], uid});
        const auto grants = only<mcan::LoginGrant>(decoded(table.tell(mcan::LoginDetails{7, mids[n], {}})));
        ASSERT_EQ(grants.size(), 1u) << n;
        EXPECT_EQ(grants[0].slaveUid, std::uint32_t(n) << 24 | n);
        EXPECT_EQ(grants[0].flags, 0) << "never the boot-loader bit";
        nodes.insert(grants[0].node);
    }
    EXPECT_EQ(nodes.size(), 31u);
    EXPECT_EQ(*nodes.begin(), 43);
    EXPECT_EQ(*nodes.rbegin(), 43 + 2 * 30);
}

TEST(HandheldMaster, AStageOutOfOrderOrAnUnknownMidIsCountedAndNotAnswered) {
    MasterOnTable table;
    ScriptedMs1 ms1(table, 0x000204B3);
    const auto stage0 = only<mcan::LoginReply>(decoded(table.tell(mcan::LoginRequest{0, 0x00, 0})));
    ASSERT_EQ(stage0.size(), 1u);
    EXPECT_TRUE(table.tell(mcan::LoginRequest{2, 0x04, stage0[0].mid}).empty()); // stage 1 skipped
    EXPECT_TRUE(table.tell(mcan::LoginRequest{1, 0x02, 29}).empty());            // a MID nobody handed out
    EXPECT_EQ(table.master.counters().unexpected, 2u);
    EXPECT_EQ(only<mcan::LoginReply>(decoded(table.tell(mcan::LoginRequest{1, 0x02, stage0[0].mid}))).size(),
              1u);
}

TEST(HandheldMaster, AUidInStageFourThatIsNotTheOneOfStagesZeroToThreeGetsNoNode) {
    MasterOnTable table;
    std::uint8_t mid = 0;
    const std::uint8_t bytes[4] = {0x00, 0x02, 0x04, 0xB3};
    for (std::uint8_t stage = 0; stage < 4; ++stage)
        mid =
            only<mcan::LoginReply>(decoded(table.tell(mcan::LoginRequest{stage, bytes[stage], mid})))[0].mid;
    table.tell(mcan::LoginDetails{4, mid, {0x00, 0x02, 0x04, 0xB4, 0, 2, 0, 3}});
    EXPECT_TRUE(only<mcan::LoginGrant>(decoded(table.tell(mcan::LoginDetails{7, mid, {}}))).empty());
    EXPECT_TRUE(table.master.handhelds().empty());
}

TEST(HandheldMaster, LoggingInAgainKeepsItsNodeAndEndsTheOldSession) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 first(table, 0x000204B3);
    ASSERT_TRUE(first.logIn());
    first.upgrade();
    first.take(FirstLoco);
    ScriptedMs1 again(table, 0x000204B3); // unplugged and plugged in
    ASSERT_TRUE(again.logIn());
    EXPECT_EQ(again.node(), first.node());
    ASSERT_EQ(table.master.handhelds().size(), 1u);
    EXPECT_FALSE(table.master.handhelds()[0].loco.has_value())
        << "its locomotive was given up with the old session";
}

TEST(HandheldMaster, ASecondHandheldCannotStealALocomotive) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 first(table, 0x00000001, "FIRST");
    ScriptedMs1 second(table, 0x00000002, "SECOND");
    ASSERT_TRUE(first.logIn() && second.logIn());
    first.upgrade();
    second.upgrade();

    const auto granted = only<mcan::Throttle>(first.take(FirstLoco));
    ASSERT_EQ(granted.size(), 2u);
    EXPECT_EQ(granted[0].state, 0x0008);              // the echo: granted
    EXPECT_EQ(granted[1].at.node, second.node() - 1); // and the second is told it is held
    EXPECT_EQ(granted[1].state, 0xFFFF);
    const auto refused = only<mcan::Throttle>(second.take(FirstLoco));
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_EQ(refused[0].state, 0xFFFF); // held
    table.railway.intents.clear();
    second.drive(FirstLoco, 1, 0x40);
    EXPECT_TRUE(table.railway.intents.empty()) << "the refused handheld drove the locomotive";
    EXPECT_EQ(table.master.counters().refused, 1u);

    // The first gives it back: the second is told it is free and may take it.
    const auto told = table.tell(mcan::Throttle{first.at(FirstLoco, mcan::prio::Throttle), 1, 0x0008, 1});
    bool freed = false;
    for (const can::CanFrame& frame : told)
        if ((frame.id & 0x7F) == second.node() - 1u && frame.dlc == 6 && frame.data[2] == 0 &&
            frame.data[3] == 0)
            freed = true;
    EXPECT_TRUE(freed);
    EXPECT_EQ(only<mcan::Throttle>(second.take(FirstLoco)).at(0).state, 0x0008);
}

TEST(HandheldMaster, WhatAHandheldDoesDrivesTheRailway) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 ms1(table, 0x000204B3);
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    ms1.take(FirstLoco);
    table.railway.intents.clear();
    EXPECT_TRUE(ms1.drive(FirstLoco, 1, 64).empty()) << "a slave's change is not acknowledged (7.3)";
    ms1.drive(FirstLoco, 1, 0x80 | 5);
    ms1.drive(FirstLoco, 2, 1);
    ms1.drive(FirstLoco, 4, 1);
    EXPECT_EQ(table.railway.intents,
              (std::vector<std::string>{"speed 0x4006 504", "direction 0x4006 reverse", "speed 0x4006 39",
                                        "function 0x4006 f0 on", "function 0x4006 f2 on"}));
    const auto* shown = handheldOf(table.master, 0x000204B3);
    ASSERT_NE(shown, nullptr);
    EXPECT_EQ(shown->speed, 5);
    EXPECT_FALSE(shown->forward);
    EXPECT_EQ(shown->functions, 0b101u);
    EXPECT_EQ(shown->locoName, "BR 218 Ost");
}

TEST(HandheldMaster, RailwayChangesReachOnlyTheHandheldsThatShowTheLocomotive) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 first(table, 0x00000001);
    ScriptedMs1 second(table, 0x00000002);
    ASSERT_TRUE(first.logIn() && second.logIn());
    first.upgrade();
    second.upgrade();
    first.take(FirstLoco);
    second.take(SecondLoco);
    table.sent.clear();
    table.railway.drives[Br218] = {500, true, 0b001};
    table.master.locoChanged(Br218);
    ASSERT_EQ(table.sent.size(), 2u);
    for (const can::CanFrame& frame : table.sent) {
        EXPECT_EQ(frame.id & 0x7F, first.node() - 1u) << "only the handheld that shows it";
        EXPECT_EQ(mcan::readSession(frame.id).prio, mcan::prio::Master);
    }
    const auto values = only<mcan::FunctionValue>(decoded(table.sent, mcan::HandleRole::Loco));
    ASSERT_EQ(values.size(), 2u);
    EXPECT_EQ(values[0].function, 1);
    EXPECT_EQ(values[0].value, 64); // 500 of 1000 is step 64 of 127
    EXPECT_EQ(values[1].function, 2);
    EXPECT_EQ(values[1].value, 1);
    table.sent.clear();
    table.master.locoChanged(Br218);
    EXPECT_TRUE(table.sent.empty()) << "nothing changed, nothing told";
}

TEST(HandheldMaster, TheStopKeyStopsTheRailwayAndEveryHandheldSeesIt) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 first(table, 0x00000001);
    ScriptedMs1 second(table, 0x00000002);
    ASSERT_TRUE(first.logIn() && second.logIn());
    first.upgrade();
    second.upgrade();
    table.railway.intents.clear();
    const auto told = table.tell(mcan::StatusValue{first.at(3, mcan::prio::SlaveDrive), 1, 1});
    EXPECT_EQ(table.railway.intents, std::vector<std::string>{"power off"});
    const auto status = only<mcan::StatusValue>(decoded(told, mcan::HandleRole::SystemStatus));
    ASSERT_EQ(status.size(), 4u); // stop and no short circuit, to each of the two
    EXPECT_EQ(status[0].index, 1);
    EXPECT_EQ(status[0].value, 1);
    EXPECT_EQ(status[0].at.prio, mcan::prio::Status);
    EXPECT_EQ(status[2].at.node, second.node() - 1);
}

TEST(HandheldMaster, ThePowerStateOfTheStationReachesEveryHandheldAndUnknownPowerIsStop) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 ms1(table, 0x00000001);
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    table.railway.power = std::nullopt; // the station fell silent
    table.sent.clear();
    table.master.powerChanged();
    const auto status = only<mcan::StatusValue>(decoded(table.sent, mcan::HandleRole::SystemStatus));
    ASSERT_EQ(status.size(), 2u);
    EXPECT_EQ(status[0].value, 1);
    const auto asked = only<mcan::StatusValue>(
        decoded(table.tell(mcan::StatusQuery{ms1.at(3), 1, false}), mcan::HandleRole::SystemStatus));
    EXPECT_EQ(asked.at(0).value, 1);
}

TEST(HandheldMaster, AShortCircuitReachesEveryHandheldUntilThePowerIsOnAgain) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 ms1(table, 0x00000001);
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    table.railway.power = false; // the station switched the track off on the overload
    table.sent.clear();
    table.master.shortCircuitReported();
    auto status = only<mcan::StatusValue>(decoded(table.sent, mcan::HandleRole::SystemStatus));
    ASSERT_EQ(status.size(), 2u);
    EXPECT_EQ(status[0].index, 1);
    EXPECT_EQ(status[0].value, 1) << "stopped";
    EXPECT_EQ(status[1].index, 2);
    EXPECT_EQ(status[1].value, 1) << "short circuit";
    const auto asked = only<mcan::StatusValue>(
        decoded(table.tell(mcan::StatusQuery{ms1.at(3), 2, false}), mcan::HandleRole::SystemStatus));
    EXPECT_EQ(asked.at(0).value, 1) << "a handheld that asks is told too";

    table.railway.power = true; // Go from anywhere
    table.sent.clear();
    table.master.powerChanged();
    status = only<mcan::StatusValue>(decoded(table.sent, mcan::HandleRole::SystemStatus));
    ASSERT_EQ(status.size(), 2u);
    EXPECT_EQ(status[0].value, 0);
    EXPECT_EQ(status[1].value, 0) << "the power back on ends the short circuit";
}

TEST(HandheldMaster, ASilentHandheldIsPolledThenDroppedAndItsLocomotiveFreed) {
    mcanhandhelds::MasterSettings settings;
    settings.silentAfter = std::chrono::milliseconds(150);
    settings.masterPollEvery = std::chrono::milliseconds(30);
    settings.masterPolls = 3;
    settings.tick = std::chrono::milliseconds(10);
    MasterOnTable table(settings);
    twoLocos(table);
    QSignalSpy events(&table.master, &mcanhandhelds::HandheldMaster::event);
    ScriptedMs1 ms1(table, 0x000204B3);
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    ms1.take(FirstLoco);
    table.sent.clear();
    ASSERT_TRUE(waitFor([&] { return table.master.handhelds().at(0).state == HandheldState::Offline; }));
    const auto polls = only<mcan::MasterPoll>(decoded(table.sent));
    EXPECT_EQ(polls.size(), 3u);
    std::vector<HandheldEvent::Kind> kinds;
    for (const auto& arguments : events)
        kinds.push_back(arguments.at(0).value<HandheldEvent>().kind);
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), HandheldEvent::Kind::Silent), kinds.end());
    EXPECT_EQ(kinds.back(), HandheldEvent::Kind::Lost);
    ScriptedMs1 other(table, 0x00000002);
    ASSERT_TRUE(other.logIn());
    other.upgrade();
    EXPECT_EQ(only<mcan::Throttle>(other.take(FirstLoco)).at(0).state, 0x0008)
        << "the lost handheld's locomotive is free";
}

TEST(HandheldMaster, ASilentHandheldThatAnswersIsBack) {
    mcanhandhelds::MasterSettings settings;
    settings.silentAfter = std::chrono::milliseconds(100);
    settings.tick = std::chrono::milliseconds(10);
    MasterOnTable table(settings);
    ScriptedMs1 ms1(table, 0x000204B3);
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    ASSERT_TRUE(waitFor([&] { return table.master.handhelds().at(0).state == HandheldState::Silent; }));
    table.tell(mcan::PollReply{ms1.at(1, mcan::prio::Master), 0x000204B3});
    EXPECT_EQ(table.master.handhelds().at(0).state, HandheldState::Online);
}

TEST(HandheldMaster, AnotherMasterMakesItFallSilentAndOnlyWatch) {
    MasterOnTable table;
    twoLocos(table);
    QSignalSpy master(&table.master, &mcanhandhelds::HandheldMaster::masterChanged);
    // A CS2 answers a login on the bus (its stage-0 reply to another MS1).
    table.tell(mcan::LoginReply{0, 0x00, 5, {0x43, 0x53, 0x32, 0x01, 0x00, 0x01, 0x00, 0x01}});
    EXPECT_FALSE(table.master.isMaster());
    ASSERT_EQ(master.count(), 1);
    EXPECT_FALSE(master.at(0).at(0).toBool());
    EXPECT_EQ(table.master.watching(), mcanhandhelds::Watching::AnotherMaster);
    EXPECT_EQ(table.master.otherMasterNode(), 0) << "a login reply does not say the master's node";
    // Its handheld logs in there: Stellwerk says nothing, and shows it.
    table.sent.clear();
    table.tell(mcan::LoginRequest{0, 0x00, 0});
    table.tell(mcan::LoginGrant{5, 0x000204B3, 2, 43, true, 0});
    table.tell(mcan::Poll{{mcan::prio::Master, 1, 43}, 42});
    EXPECT_TRUE(table.sent.empty());
    const auto shown = table.master.handhelds();
    ASSERT_EQ(shown.size(), 1u);
    EXPECT_FALSE(shown[0].ours);
    EXPECT_EQ(shown[0].state, HandheldState::Online);
}

TEST(HandheldMaster, ItsOwnHandheldsStayShownAsWatchedWhenAnotherMasterSpeaks) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 ms1(table, 0x000204B3);
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    table.tell(mcan::PollAnswer{
        {mcan::prio::Master, 1, 44}, 0, 44, 0x43533201}); // a master on node 44 answers a poll
    EXPECT_EQ(table.master.watching(), mcanhandhelds::Watching::AnotherMaster);
    EXPECT_EQ(table.master.otherMasterNode(), 44) << "a session frame names the master's node";
    const auto shown = table.master.handhelds();
    ASSERT_EQ(shown.size(), 1u) << "the handheld it was the master of is still shown";
    EXPECT_EQ(shown[0].uid, 0x000204B3u);
    EXPECT_FALSE(shown[0].ours);
}

TEST(HandheldMaster, ACentralStationThatSpeaksIsNamedAsTheReasonToWatch) {
    MasterOnTable table;
    table.master.standDown(mcanhandhelds::Watching::CentralStation);
    table.tell(mcan::LoginReply{0, 0x00, 5, {0x43, 0x53, 0x32, 0x01, 0x00, 0x01, 0x00, 0x01}});
    EXPECT_EQ(table.master.watching(), mcanhandhelds::Watching::CentralStation);
}

TEST(HandheldMaster, ItsOwnFramesEchoedByAGatewayAreNotAnotherMaster) {
    MasterOnTable table;
    ScriptedMs1 ms1(table, 0x000204B3);
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    const std::vector<can::CanFrame> ours = table.sent;
    table.master.receive(ours);
    EXPECT_TRUE(table.master.isMaster());
}

TEST(HandheldMaster, BadInputIsCountedUnansweredAndNeverEndsAnotherHandheldsSession) {
    MasterOnTable table;
    twoLocos(table);
    ScriptedMs1 ms1(table, 0x000204B3);
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    const std::uint64_t before = table.master.counters().unexpected;
    EXPECT_TRUE(table.tell(mcan::Poll{{mcan::prio::Master, 1, 77}, 76}).empty()); // unknown node
    EXPECT_TRUE(table.tell(mcan::LocoQuery{ms1.at(0x0100), 0x03, 0}).empty());    // handle nobody issued
    EXPECT_TRUE(table.tell(mcan::NameRequest{ms1.at(FirstLoco), 3}).empty());     // offset 3
    EXPECT_TRUE(table.tell(can::CanFrame::extendedFrame(0x18000DAB, std::vector<std::uint8_t>{9}))
                    .empty()); // garbage
    EXPECT_EQ(table.master.counters().unexpected, before + 4);
    EXPECT_EQ(only<mcan::PollAnswer>(ms1.poll()).size(), 1u) << "the handheld's session goes on";
    EXPECT_EQ(table.master.handhelds().at(0).state, HandheldState::Online);
}

TEST(HandheldMaster, StacksAndNamesAreRememberedByUidAndToldToTheHandheld) {
    MasterOnTable table;
    twoLocos(table);
    mcanhandhelds::MemoryHandheldBook book;
    table.master.setBook(&book);
    ScriptedMs1 ms1(table, 0x000204B3, "KS MS1");
    ASSERT_TRUE(ms1.logIn());
    ms1.upgrade();
    table.sent.clear();
    table.master.setStack(0x000204B3, {Koef});
    const auto changes = decoded(table.sent);
    ASSERT_EQ(only<mcan::StackDelete>(changes).size(), 1u);
    EXPECT_EQ(only<mcan::StackDelete>(changes)[0].locoHandle, FirstLoco);
    table.sent.clear();
    table.master.rename(0x000204B3, QStringLiteral("Küche"));
    const auto segments = only<mcan::NameSegment>(decoded(table.sent));
    ASSERT_EQ(segments.size(), 4u);
    EXPECT_EQ(std::string(segments[0].chars.data(), 4), "Kuec");
    EXPECT_EQ(book.load(0x000204B3)->stack, std::vector<std::uint32_t>{Koef});
    EXPECT_EQ(book.load(0x000204B3)->name, "Kueche");

    ScriptedMs1 again(table, 0x000204B3, "Kueche"); // next session: the remembered stack
    ASSERT_TRUE(again.logIn());
    const auto first =
        only<mcan::LocoListAnswer>(decoded(table.tell(mcan::LocoListQuery{again.at(2), 0x80, 0})));
    ASSERT_EQ(first.size(), 1u);
    const auto name =
        only<mcan::NameSegment>(decoded(table.tell(mcan::NameRequest{again.at(first[0].next), 0})));
    EXPECT_EQ(std::string(name.at(0).chars.data(), 4), "Koef");
    EXPECT_EQ(
        only<mcan::LocoListEnd>(decoded(table.tell(mcan::LocoListQuery{again.at(2), 0x80, first[0].next})))
            .size(),
        1u);
}

TEST(HandheldMaster, AHandheldInItsBootLoaderIsShownAndOnlyEverSilenced) {
    MasterOnTable table;
    QSignalSpy events(&table.master, &mcanhandhelds::HandheldMaster::event);
    EXPECT_TRUE(table.tell(mcan::FlashReady{0x000204B3}).empty());
    ASSERT_EQ(table.master.handhelds().size(), 1u);
    EXPECT_EQ(table.master.handhelds()[0].state, HandheldState::FlashMode);
    ASSERT_EQ(events.count(), 1);
    EXPECT_EQ(events.at(0).at(0).value<HandheldEvent>().kind, HandheldEvent::Kind::FlashMode);
    table.master.silenceBootLoader(0x000204B3);
    ASSERT_EQ(table.sent.size(), 1u);
    EXPECT_EQ(table.sent[0].id, 0x1C00007Fu); // the abort of 9.6: flash handle 0
}
