// The MS1's login (notes B§3.1) and its life around it: two MS1s whose UIDs begin alike, unplugging, a
// master that goes away, a master that sends it into flash mode.

#include "Ms1TestSupport.h"
#include "TestMaster.h"
#include "sim/SimulatedBus.h"

namespace stellwerk::sim::test {
namespace {

constexpr std::uint32_t TraceUid = 0x000204B3;
constexpr std::uint32_t NeighbourUid = 0x000204C5; // the same first three bytes

const CanFrame StageZero = frame("1C00007E 0");
const CanFrame TracePoll = frame("0C0007AB 4 00 00 00 2A");

bool isLogin(const CanFrame& f) {
    return mcan::layoutOf(f.id) == mcan::Layout::Login;
}

// One MS1 and the test master on a simulated bus.
class Ms1OnBus : public ::testing::Test {
protected:
    explicit Ms1OnBus(SimulatedMs1::Options options = fastMs1()) : ms1_(options), sent_(ms1_) {
        bus_.attach(master_);
        bus_.attach(ms1_);
        QObject::connect(&ms1_, &SimulatedMs1::upgradeDone, &ms1_, [this] { ++upgrades_; });
        QObject::connect(&ms1_, &SimulatedMs1::masterLost, &ms1_, [this] { ++masterLost_; });
    }

    bool online() {
        return waitFor([this] { return ms1_.phase() == SimulatedMs1::Phase::Online; });
    }

    SimulatedBus bus_;
    TestMaster master_;
    SimulatedMs1 ms1_;
    Emitted sent_;
    int upgrades_ = 0;
    int masterLost_ = 0;
};

TEST_F(Ms1OnBus, LogsInWithStagesZeroToThreeWithoutDataThenFourToSevenBackToBack) {
    ms1_.plugIn();
    ASSERT_TRUE(online());
    const std::vector<CanFrame> login(sent_.all.begin(), sent_.all.begin() + 8);
    EXPECT_EQ(login, frames({"1C00007E 0", "1C08B07E 0", "1C11307E 0", "1ECDB07E 0",
                             "1C02307E 8 00 02 04 B3 00 02 00 03", "1C02B07E 8 00 00 00 97 01 00 40 10",
                             "1C03307E 8 01 00 00 67 00 00 40 10", "1C03B07E 8 00 00 40 10 01 08 00 10"}));
    EXPECT_EQ(sent_.all[8], frame("18000A2B 2 40 2B")) << "then the SD handle request";
    EXPECT_EQ(ms1_.memory().link.node, master_.nodeOf(TraceUid));
}

// Both send identical frames until stage 3, which the bus carries as one; there the lower byte (B3) wins
// arbitration and the echo; the other gives up, tries again after the wait, and gets the next node pair.
TEST(Ms1Collision, TwoMs1sWhoseUidsBeginAlikeBothLogInWithDifferentNodes) {
    SimulatedBus bus;
    TestMaster master;
    SimulatedMs1 neighbour(fastMs1(NeighbourUid, "MS1 2"));
    SimulatedMs1 trace(fastMs1(TraceUid, "MS1 1"));
    Emitted neighbourSent(neighbour);
    bus.attach(master);
    bus.attach(neighbour); // first on the bus, first to send: arbitration decides all the same
    bus.attach(trace);
    neighbour.plugIn();
    trace.plugIn();
    ASSERT_TRUE(waitFor([&] {
        return neighbour.phase() == SimulatedMs1::Phase::Online &&
               trace.phase() == SimulatedMs1::Phase::Online;
    }));

    EXPECT_EQ(trace.memory().link.node, 43);
    EXPECT_EQ(neighbour.memory().link.node, 45);
    std::vector<CanFrame> stageZeros;
    std::ranges::copy_if(master.heard, std::back_inserter(stageZeros),
                         [](const CanFrame& f) { return f == StageZero; });
    EXPECT_EQ(stageZeros.size(), 2u) << "one merged first attempt, one retry";
    const std::vector<CanFrame> firstTry(neighbourSent.all.begin(), neighbourSent.all.begin() + 5);
    EXPECT_EQ(firstTry, frames({"1C00007E 0", "1C08B07E 0", "1C11307E 0", "1F15B07E 0", "1C00007E 0"}))
        << "the neighbour lost at stage 3 and started again at stage 0 (with a new MID from the master)";
}

TEST_F(Ms1OnBus, UnpluggedItFallsSilentAtOnceAndPluggedInItLogsInAgainFromStageZero) {
    ms1_.plugIn();
    ASSERT_TRUE(online());
    ms1_.unplug();
    const std::size_t before = sent_.all.size();
    QTest::qWait(200); // ten poll periods
    EXPECT_EQ(sent_.all.size(), before) << "no frame at all";
    EXPECT_EQ(ms1_.phase(), SimulatedMs1::Phase::Unplugged);
    master_.push(43, mcan::MasterPoll{{mcan::prio::Master, TestMaster::PollHandle, 0}, 43});
    QTest::qWait(50);
    EXPECT_EQ(sent_.all.size(), before) << "not even to a master's poll";

    ms1_.plugIn();
    ASSERT_FALSE(sent_.since(before).empty());
    EXPECT_EQ(sent_.all[before], StageZero);
    ASSERT_TRUE(online());
    EXPECT_EQ(upgrades_, 2);
}

// The master makes the MS1 silent at the end of the upgrade: it polls exactly 30 times, then says "no
// master" and starts the login again.
TEST_F(Ms1OnBus, WithoutAnswersToThirtyPollsItLogsInAgain) {
    QObject::connect(&ms1_, &SimulatedMs1::upgradeDone, &ms1_, [this] { master_.silent = true; });
    ms1_.plugIn();
    ASSERT_TRUE(online());
    const auto firstPoll = std::ranges::find(sent_.all, TracePoll);
    ASSERT_NE(firstPoll, sent_.all.end());
    const std::size_t from = std::size_t(firstPoll - sent_.all.begin());
    ASSERT_TRUE(waitFor([this] { return masterLost_ == 1; }));
    const std::vector<CanFrame> after = sent_.since(from);
    ASSERT_GE(after.size(), 31u);
    EXPECT_EQ(std::vector<CanFrame>(after.begin(), after.begin() + 30), std::vector<CanFrame>(30, TracePoll));
    EXPECT_EQ(after[30], StageZero);
    EXPECT_EQ(ms1_.phase(), SimulatedMs1::Phase::LoggingIn);
}

// Without any master the MS1 repeats its stage-0 frame after each wait (8: "cyclic login frames").
TEST_F(Ms1OnBus, WithoutAMasterItRepeatsStageZero) {
    master_.silent = true;
    ms1_.plugIn();
    ASSERT_TRUE(waitFor([this] { return sent_.all.size() >= 3; }));
    EXPECT_EQ(sent_.all, std::vector<CanFrame>(sent_.all.size(), StageZero));
}

// Granted with the flash bit, it says on node 127 that it is ready to be flashed, and nothing else ever.
TEST_F(Ms1OnBus, TheFlashBitMakesItSayFlashReadinessAndNothingElse) {
    master_.flash = true;
    int flashModes = 0;
    QObject::connect(&ms1_, &SimulatedMs1::flashModeEntered, &ms1_, [&] { ++flashModes; });
    ms1_.plugIn();
    ASSERT_TRUE(waitFor([this] { return ms1_.phase() == SimulatedMs1::Phase::FlashMode; }));
    master_.push(43, mcan::MasterPoll{{mcan::prio::Master, TestMaster::PollHandle, 0}, 43});
    master_.push(43, mcan::StackSizeRequest{{mcan::prio::Data, TestMaster::SdHandle, 0}});
    QTest::qWait(200);
    std::vector<CanFrame> afterLogin;
    std::ranges::copy_if(sent_.all, std::back_inserter(afterLogin),
                         [](const CanFrame& f) { return !isLogin(f); });
    EXPECT_EQ(afterLogin, frames({"1C02807F 4 00 02 04 B3"}));
    EXPECT_EQ(flashModes, 1);
    EXPECT_EQ(upgrades_, 0);
}

} // namespace
} // namespace stellwerk::sim::test
