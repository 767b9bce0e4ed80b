// The MS1 in operation (notes B§3.3-3.8): its keys as frames, and what the master pushes changing what it
// shows.

#include "Ms1TestSupport.h"
#include "TestMaster.h"
#include "sim/SimulatedBus.h"

namespace stellwerk::sim::test {
namespace {

constexpr std::uint8_t Node = 43;
constexpr std::uint16_t Loco9 = 0x0009;
constexpr std::uint16_t LocoA = 0x000A;

mcan::Address master(std::uint8_t prio, std::uint16_t handle) {
    return {prio, handle, 0}; // TestMaster::push puts in the master's node
}

// An MS1 online with the trace's loco (given an f0) taken, and the test master.
class Ms1Online : public ::testing::Test {
protected:
    void SetUp() override {
        master_.stack[0].functionKinds = {1};
        bus_.attach(master_);
        bus_.attach(ms1_);
        QObject::connect(&ms1_, &SimulatedMs1::displayChanged, &ms1_, [this] { ++changes_; });
        QObject::connect(&ms1_, &SimulatedMs1::locoTaken, &ms1_,
                         [this](int index) { taken_.push_back(index); });
        QObject::connect(&ms1_, &SimulatedMs1::locoRefused, &ms1_,
                         [this](int index) { refused_.push_back(index); });
        ms1_.plugIn();
        ASSERT_TRUE(waitFor([this] { return !taken_.empty(); })) << "the first entry taken after five polls";
        taken_.clear();
    }

    // Frames the MS1 sent from now on, without its polls.
    std::vector<CanFrame> sentSince(std::size_t from) const {
        std::vector<CanFrame> result;
        for (const CanFrame& f : sent_.since(from))
            if (mcan::readSession(f.id).handle != Ms1Link::PollHandle)
                result.push_back(f);
        return result;
    }
    void settle() { QTest::qWait(60); }

    SimulatedBus bus_;
    TestMaster master_;
    SimulatedMs1 ms1_{fastMs1()};
    Emitted sent_{ms1_};
    int changes_ = 0;
    std::vector<int> taken_;
    std::vector<int> refused_;
};

TEST_F(Ms1Online, TheKnobSendsSpeedAndDirectionAsFunctionOneWithPriority010) {
    const std::size_t from = sent_.all.size();
    ASSERT_TRUE(ms1_.setSpeed(20, SimulatedMs1::Direction::Reverse));
    ASSERT_TRUE(ms1_.setFunction(0, true));
    EXPECT_EQ(sentSince(from), frames({"0800252B 3 01 00 94", "0800252B 3 02 00 01"}));
    EXPECT_EQ(ms1_.shownLoco()->speed, 20);
    EXPECT_TRUE(ms1_.shownLoco()->reverse);
    EXPECT_EQ(ms1_.shownLoco()->functions.at(0).value, 1);
    EXPECT_FALSE(ms1_.setSpeed(128, SimulatedMs1::Direction::Forward));
    EXPECT_FALSE(ms1_.setFunction(1, true)) << "the loco has f0 only";
    EXPECT_EQ(sentSince(from).size(), 2u);
}

TEST_F(Ms1Online, TheStopKeyAsksTheMasterWhichSaysStop) {
    const std::size_t from = sent_.all.size();
    ASSERT_TRUE(ms1_.pressStop());
    EXPECT_FALSE(ms1_.memory().stopped) << "it shows what the master says";
    ASSERT_TRUE(waitFor([this] { return ms1_.memory().stopped; }));
    ASSERT_TRUE(ms1_.pressGo());
    ASSERT_TRUE(waitFor([this] { return !ms1_.memory().stopped; }));
    EXPECT_EQ(sentSince(from), frames({"08000D2B 3 01 00 01", "08000D2B 3 01 00 00"}));
}

TEST_F(Ms1Online, ALocoHeldByTheMasterIsRefusedAndCannotBeDriven) {
    master_.holdsLocos = true;
    const std::size_t from = sent_.all.size();
    ASSERT_TRUE(ms1_.takeLoco(0));
    ASSERT_TRUE(waitFor([this] { return !refused_.empty(); }));
    EXPECT_EQ(refused_, std::vector<int>{0});
    EXPECT_EQ(ms1_.memory().control, Ms1Control::HeldByMaster);
    EXPECT_FALSE(ms1_.setSpeed(10, SimulatedMs1::Direction::Forward));
    EXPECT_EQ(sentSince(from), frames({"1400242B 6 03 00 00 08 00 01"}));
}

TEST_F(Ms1Online, StopAndShortCircuitFromTheMasterAreShown) {
    master_.push(Node, mcan::StatusValue{master(mcan::prio::Status, TestMaster::SyHandle), 1, 1});
    ASSERT_TRUE(waitFor([this] { return ms1_.memory().stopped; }));
    master_.push(Node, mcan::StatusValue{master(mcan::prio::Status, TestMaster::SyHandle), 2, 1});
    ASSERT_TRUE(waitFor([this] { return ms1_.memory().shortCircuit; }));
    master_.push(Node, mcan::StatusValue{master(mcan::prio::Status, TestMaster::SyHandle), 1, 0});
    ASSERT_TRUE(waitFor([this] { return !ms1_.memory().stopped; }));
    EXPECT_GE(changes_, 3);
}

TEST_F(Ms1Online, SpeedAndFunctionsTheMasterDrivesAreShown) {
    const std::size_t from = sent_.all.size();
    master_.push(Node, mcan::FunctionValue{master(mcan::prio::Master, Loco9), 1, 0x85});
    master_.push(Node, mcan::FunctionValue{master(mcan::prio::Master, Loco9), 2, 1});
    ASSERT_TRUE(waitFor([this] { return ms1_.shownLoco()->functions.at(0).value == 1; }));
    EXPECT_EQ(ms1_.shownLoco()->speed, 5);
    EXPECT_TRUE(ms1_.shownLoco()->reverse);
    EXPECT_TRUE(sentSince(from).empty()) << "the MS1 acknowledges nothing";
}

// 7.7.2: the MS1 asks about the added loco as in the upgrade; 7.7.1: when the shown loco goes, it takes
// the other.
TEST_F(Ms1Online, StackAddAndDeleteChangeTheStack) {
    master_.stack.push_back({LocoA, "BR 218", 2, 2, {}});
    const std::size_t from = sent_.all.size();
    master_.push(Node, mcan::StackAdd{master(mcan::prio::Data, TestMaster::SyHandle), LocoA});
    ASSERT_TRUE(waitFor(
        [this] { return ms1_.memory().stack.size() == 2 && ms1_.memory().stack[1].name == "BR 218"; }));
    EXPECT_EQ(sent_.onHandle(LocoA, from),
              frames({"180028AB 4 40 03 00 00", "180028AB 4 40 01 00 00", "180028AB 4 40 01 01 00",
                      "1800292B 2 01 01", "1800292B 2 01 00", "1800292B 2 02 01", "1800292B 4 01 02 00 00",
                      "1800292B 4 01 02 01 00", "1800292B 4 01 02 02 00", "180028AB 4 40 04 00 00",
                      "1800282B 2 03 00", "180028AB 4 02 00 00 00", "180028AB 4 02 00 00 04"}));
    EXPECT_EQ(ms1_.memory().stack[1].type, 2);
    EXPECT_EQ(ms1_.memory().stack[1].railFormat, 2);

    const std::size_t beforeDelete = sent_.all.size();
    master_.push(Node, mcan::StackDelete{master(mcan::prio::Data, TestMaster::SyHandle), Loco9});
    ASSERT_TRUE(waitFor([this] { return !taken_.empty(); }));
    EXPECT_EQ(sentSince(beforeDelete), frames({"1400282B 6 03 00 00 08 00 01"}));
    ASSERT_EQ(ms1_.memory().stack.size(), 1u);
    EXPECT_EQ(ms1_.shownLoco()->name, "BR 218");
    EXPECT_EQ(ms1_.memory().control, Ms1Control::Granted);
}

// 7.5: the master renames the MS1 on its SD handle; it repeats each segment from its own node.
TEST_F(Ms1Online, ARenameChangesItsNameAndIsRepeated) {
    const std::size_t from = sent_.all.size();
    master_.push(Node, mcan::NameSegment{
                           master(mcan::prio::Data, TestMaster::SdHandle), 0, 4, {'B', 'A', 'H', 'N'}, 0});
    master_.push(Node, mcan::NameSegment{
                           master(mcan::prio::Data, TestMaster::SdHandle), 4, 3, {'H', 'F', '\0', 0}, 0});
    ASSERT_TRUE(waitFor([this] { return ms1_.identity().name == "BAHNHF"; }));
    EXPECT_EQ(sentSince(from),
              frames({"180020AB 8 02 00 00 00 42 41 48 4E", "180020AB 7 02 00 00 04 48 46 00"}));
    const std::size_t asked = sent_.all.size();
    master_.push(Node, mcan::NameRequest{master(mcan::prio::Data, TestMaster::SdHandle), 4});
    ASSERT_TRUE(waitFor([&] { return sentSince(asked).size() == 1; }));
    EXPECT_EQ(sentSince(asked), frames({"180020AB 7 02 00 00 04 48 46 00"}));
}

// 7.6: the master takes the loco (FFFF): the MS1 only watches; the master frees it (0000): the MS1 chooses
// it again and gets it.
TEST_F(Ms1Online, TheMasterTakingAndFreeingTheLocoIsFollowed) {
    master_.push(Node, mcan::Throttle{master(mcan::prio::Throttle, Loco9), 0, 0xFFFF, 1});
    ASSERT_TRUE(waitFor([this] { return ms1_.memory().control == Ms1Control::HeldByMaster; }));
    const std::size_t from = sent_.all.size();
    master_.push(Node, mcan::Throttle{master(mcan::prio::Throttle, Loco9), 0, 0x0000, 1});
    ASSERT_TRUE(waitFor([this] { return !taken_.empty(); }));
    EXPECT_EQ(sentSince(from), frames({"1400242B 6 03 01 00 08 00 01"}));
    EXPECT_EQ(ms1_.memory().control, Ms1Control::Granted);
}

TEST_F(Ms1Online, AMasterPollIsAnsweredWithItsUid) {
    master_.push(Node, mcan::MasterPoll{master(mcan::prio::Master, TestMaster::PollHandle), Node});
    EXPECT_TRUE(waitFor([&] { return sent_.count(frame("0C0007AB 8 03 00 00 00 00 02 04 B3")) == 1; }));
}

} // namespace
} // namespace stellwerk::sim::test
