// A SimulatedMs1 (UID 0x000204B3, "KS MS1") against the ECoS of the chapter-11 trace of seed 002, read in
// place: the MS1 must send exactly the trace's 48 slave frames, the same bytes, each thread of questions
// in the trace's order (notes B§3.2 and B§4.2: the interleaving of the threads may differ).

#include "Ms1TestSupport.h"
#include "SeedTrace.h"
#include "TraceMaster.h"
#include "sim/SimulatedBus.h"

#include <map>
#include <string>

namespace stellwerk::sim::test {
namespace {

std::vector<CanFrame> slaveFrames(const std::vector<CanFrame>& trace) {
    std::vector<CanFrame> result;
    for (const CanFrame& f : trace)
        if (senderOf(f) == TraceSender::Slave)
            result.push_back(f);
    return result;
}

// A thread of the MS1's conversation: the login, or the frames about one handle (start, SD, SY, a
// locomotive, the poll handle). Each keeps its order whatever the interleaving.
std::string threadOf(const CanFrame& f) {
    if (mcan::layoutOf(f.id) == mcan::Layout::Login)
        return "login";
    return "handle " + std::to_string(mcan::readSession(f.id).handle);
}

std::map<std::string, std::vector<CanFrame>> byThread(const std::vector<CanFrame>& frames) {
    std::map<std::string, std::vector<CanFrame>> threads;
    for (const CanFrame& f : frames)
        threads[threadOf(f)].push_back(f);
    return threads;
}

std::vector<CanFrame> sorted(std::vector<CanFrame> frames) {
    std::ranges::sort(frames, [](const CanFrame& a, const CanFrame& b) {
        return std::tie(a.id, a.dlc, a.data) < std::tie(b.id, b.dlc, b.data);
    });
    return frames;
}

class Ms1TraceTest : public ::testing::Test {
protected:
    void SetUp() override {
        trace_ = seeds::chapter11Trace(seeds::McanSeed002);
        ASSERT_EQ(trace_.size(), 99u) << "chapter 11 of " << seeds::seedPath(seeds::McanSeed002);
        expected_ = slaveFrames(trace_);
        ASSERT_EQ(expected_.size(), 48u);
    }

    std::vector<CanFrame> trace_;
    std::vector<CanFrame> expected_;
};

TEST_F(Ms1TraceTest, SendsTheTraceSlaveFramesToTheTraceMaster) {
    SimulatedBus bus;
    TraceMaster master(trace_);
    SimulatedMs1 ms1(fastMs1());
    bus.attach(master);
    bus.attach(ms1);
    Emitted sent(ms1);
    master.start();
    ms1.plugIn();
    ASSERT_TRUE(waitFor([&] { return sent.all.size() >= expected_.size() && master.finished(); }))
        << sent.all.size() << " frames sent; the master waits for " << master.waitingFor()
        << "; frames the trace's MS1 did not send: " << ::testing::PrintToString(master.unexpected());
    const std::vector<CanFrame> first(sent.all.begin(), sent.all.begin() + std::ptrdiff_t(expected_.size()));

    EXPECT_EQ(sorted(first), sorted(expected_)) << "the same frames, byte for byte";
    EXPECT_EQ(byThread(first), byThread(expected_)) << "each thread in the trace's order";
    for (const CanFrame& later : master.unexpected())
        EXPECT_EQ(later, frame("0C0007AB 4 00 00 00 2A")) << "after the trace: polls only";
}

TEST_F(Ms1TraceTest, LearnsWhatTheTraceMasterTold) {
    SimulatedBus bus;
    TraceMaster master(trace_);
    SimulatedMs1 ms1(fastMs1());
    bus.attach(master);
    bus.attach(ms1);
    int upgrades = 0;
    std::vector<int> taken;
    QObject::connect(&ms1, &SimulatedMs1::upgradeDone, &ms1, [&] { ++upgrades; });
    QObject::connect(&ms1, &SimulatedMs1::locoTaken, &ms1, [&](int index) { taken.push_back(index); });
    master.start();
    ms1.plugIn();
    ASSERT_TRUE(waitFor([&] { return master.finished() && !taken.empty(); }))
        << "the master waits for " << master.waitingFor();

    EXPECT_EQ(ms1.phase(), SimulatedMs1::Phase::Online);
    EXPECT_EQ(upgrades, 1);
    EXPECT_EQ(taken, std::vector<int>{0});
    const Ms1Memory& memory = ms1.memory();
    EXPECT_EQ(memory.link.node, 43);
    EXPECT_EQ(memory.link.masterNode(), 42);
    EXPECT_EQ(memory.link.startHandle, 0x0002);
    EXPECT_EQ(memory.link.sdHandle, 0x0008);
    EXPECT_EQ(memory.link.syHandle, 0x0003);
    EXPECT_EQ(memory.statusTypes, (std::map<std::uint8_t, std::uint8_t>{{1, 1}, {2, 2}, {3, 4}}));
    EXPECT_FALSE(memory.stopped);
    EXPECT_FALSE(memory.shortCircuit);
    ASSERT_EQ(memory.stack.size(), 1u);
    const Ms1Loco& loco = memory.stack[0];
    EXPECT_EQ(loco.handle, 0x0009);
    EXPECT_EQ(loco.name, "003 131-0");
    EXPECT_EQ(loco.type, 3) << "steam";
    EXPECT_EQ(loco.railFormat, 3) << "Motorola";
    EXPECT_TRUE(loco.functions.empty());
    EXPECT_EQ(loco.speed, 0);
    EXPECT_FALSE(loco.reverse);
    EXPECT_EQ(memory.shown, std::optional<std::size_t>(0));
    EXPECT_EQ(memory.control, Ms1Control::Granted);
}

// The E-CAN frames of the trace (#1, #2, #58, #96-#98) are no M-CAN frames of the MS1's master: ignored.
TEST_F(Ms1TraceTest, IgnoresTheOtherDevicesOfTheBus) {
    SimulatedMs1 ms1(fastMs1());
    Emitted sent(ms1);
    ms1.plugIn();
    const std::size_t before = sent.all.size();
    for (const CanFrame& f : trace_)
        if (senderOf(f) == TraceSender::Other)
            ms1.receive(f);
    EXPECT_EQ(sent.all.size(), before);
}

} // namespace
} // namespace stellwerk::sim::test
