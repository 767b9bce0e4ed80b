// The slave side of the chapter-11 trace (an MS1 logging into an ECoS) replayed against Stellwerk's master,
// with the trace's locomotive on the railway and the ECoS's UID: the master must answer frame for frame as
// the ECoS did. The only difference allowed is the MID it hands out, which the replayed slave takes over, as
// a real MS1 does.

#include "../mcan/SeedTrace.h"
#include "MasterFixture.h"
#include "mcan/Codec.h"

#include <gtest/gtest.h>

using namespace stellwerk;

namespace {

constexpr std::uint32_t EcosUid = 0x000484D3;
constexpr std::uint32_t Loco003131 = 0x0005; // an MM2 address; the trace never shows it

bool isSlaveFrame(const can::CanFrame& frame) {
    if (!mcan::isMcan(frame))
        return false;
    if (mcan::layoutOf(frame.id) == mcan::Layout::Login)
        return !mcan::readLogin(frame.id).fromMaster;
    return mcan::layoutOf(frame.id) == mcan::Layout::Session &&
           mcan::isSlaveNode(std::uint8_t(frame.id & 0x7F));
}

bool isMasterFrame(const can::CanFrame& frame) {
    return mcan::isMcan(frame) && !isSlaveFrame(frame) && frame.id != 0x10000281; // #2 and #98: E-CAN
}

// A login frame with another MID in its id (the slave's first frame has none yet).
can::CanFrame withMid(can::CanFrame frame, std::uint8_t mid) {
    if (mcan::isMcan(frame) && mcan::layoutOf(frame.id) == mcan::Layout::Login &&
        mcan::readLogin(frame.id).mid != 0) {
        mcan::LoginId login = mcan::readLogin(frame.id);
        login.mid = mid;
        frame.id = mcan::loginId(login);
    }
    return frame;
}

struct Replay {
    std::vector<can::CanFrame> answers;
    std::vector<can::CanFrame> traceAnswers;
    std::uint8_t mid = 0;
};

Replay replay(const std::vector<can::CanFrame>& trace, mastertest::MasterOnTable& table) {
    Replay result;
    for (const can::CanFrame& frame : trace) {
        if (isMasterFrame(frame))
            result.traceAnswers.push_back(frame);
        if (!isSlaveFrame(frame))
            continue;
        for (const can::CanFrame& answer : table.tell(withMid(frame, result.mid))) {
            if (mcan::layoutOf(answer.id) == mcan::Layout::Login && result.mid == 0)
                result.mid = mcan::readLogin(answer.id).mid; // the slave takes the MID of the stage-0 reply
            result.answers.push_back(answer);
        }
    }
    return result;
}

mcanhandhelds::MasterSettings ecosLike() {
    mcanhandhelds::MasterSettings settings;
    settings.uid = EcosUid;
    settings.nodeBase = 42;
    return settings;
}

} // namespace

TEST(HandheldMasterTrace, AnswersTheTracesSlaveFrameForFrameAsTheEcosDid) {
    mastertest::MasterOnTable table(ecosLike());
    table.railway.locos = {
        {Loco003131, "003 131-0", mcanhandhelds::LocoKind::Steam, mcanhandhelds::RailFormat::Motorola, {}}};
    table.master.setRailway(&table.railway);
    const auto trace = seeds::chapter11Trace(seeds::McanSeed002);
    ASSERT_EQ(trace.size(), 99u);

    const Replay result = replay(trace, table);

    // The trace ends with the slave's poll #99; the master's answer to it is not in the trace.
    ASSERT_EQ(result.answers.size(), result.traceAnswers.size() + 1);
    EXPECT_TRUE(std::holds_alternative<mcan::PollAnswer>(mcan::decode(result.answers.back())));
    ASSERT_NE(result.mid, 0);
    for (std::size_t i = 0; i < result.traceAnswers.size(); ++i)
        EXPECT_EQ(result.answers[i], withMid(result.traceAnswers[i], result.mid))
            << "answer " << i << ": " << mcan::nameOf(mcan::decode(result.answers[i])) << " instead of "
            << mcan::nameOf(mcan::decode(result.traceAnswers[i]));
}

TEST(HandheldMasterTrace, TheReplayEndsWithTheHandheldOnlineDrivingTheTracesLocomotive) {
    mastertest::MasterOnTable table(ecosLike());
    table.railway.locos = {
        {Loco003131, "003 131-0", mcanhandhelds::LocoKind::Steam, mcanhandhelds::RailFormat::Motorola, {}}};
    table.master.setRailway(&table.railway);
    replay(seeds::chapter11Trace(seeds::McanSeed002), table);

    const std::vector<mcanhandhelds::Handheld> handhelds = table.master.handhelds();
    ASSERT_EQ(handhelds.size(), 1u);
    EXPECT_EQ(handhelds[0].uid, 0x000204B3u);
    EXPECT_EQ(handhelds[0].name, "KS MS1");
    EXPECT_EQ(handhelds[0].slaveNode, 43);
    EXPECT_EQ(handhelds[0].state, mcanhandhelds::HandheldState::Online);
    EXPECT_EQ(handhelds[0].stackSize, 10);
    EXPECT_EQ(handhelds[0].loco, std::optional<std::uint32_t>(Loco003131));
    EXPECT_EQ(handhelds[0].locoName, "003 131-0");
    // The E-CAN frames #2 and #98 (priority 100, node 1) look like M-CAN from a node nobody gave out:
    // counted, never answered.
    EXPECT_EQ(table.master.counters().unexpected, 2u);
}

TEST(HandheldMasterTrace, TheDocument000CopyReplaysTheSame) {
    mastertest::MasterOnTable table(ecosLike());
    table.railway.locos = {
        {Loco003131, "003 131-0", mcanhandhelds::LocoKind::Steam, mcanhandhelds::RailFormat::Motorola, {}}};
    table.master.setRailway(&table.railway);
    const Replay result = replay(seeds::chapter11Trace(seeds::McanSeed000), table);
    ASSERT_EQ(result.answers.size(), result.traceAnswers.size() + 1);
    for (std::size_t i = 0; i < result.traceAnswers.size(); ++i)
        EXPECT_EQ(result.answers[i], withMid(result.traceAnswers[i], result.mid)) << "answer " << i;
}
