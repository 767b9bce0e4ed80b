// What a bus reveals over time: the chapter-11 trace of the M-CAN document (an MS1 logging into an ECoS)
// read frame by frame through one context, as the monitor, the frame decoder and the CLI read a bus.

#include "busreading/BusContext.h"

#include "../mcan/SeedTrace.h"
#include "mcan/HandleRoles.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace stellwerk::busreading::test {
namespace {

using can::CanFrame;

const BusProfile Station = BusProfile::centralStation();

// The descriptions of a trace read in order through one context.
std::vector<FrameDescription> readAll(const std::vector<CanFrame>& frames, BusContext& context) {
    std::vector<FrameDescription> read;
    for (const CanFrame& frame : frames)
        read.push_back(context.read(frame, Station));
    return read;
}

class BusContextTrace : public ::testing::Test {
protected:
    void SetUp() override {
        frames = seeds::chapter11Trace(seeds::McanSeed002);
        ASSERT_EQ(frames.size(), 99u) << "the seed document is read in place from ../shared/seeds";
    }
    // Trace number (1-based, as in the notes) to frame.
    const CanFrame& frame(std::size_t number) const { return frames.at(number - 1); }

    std::vector<CanFrame> frames;
};

} // namespace

// Trace #92: the slave takes the loco whose handle (#46) and name (#77-81) the bus revealed before.
TEST_F(BusContextTrace, ALocomotiveHandleIsShownWithItsNameOnceTheBusRevealedIt) {
    BusContext context;
    const std::vector<FrameDescription> read = readAll(frames, context);
    const FrameDescription& take = read.at(91);
    EXPECT_EQ(take.protocol(), Protocol::Mcan);
    EXPECT_EQ(take.name(), "mcan.throttle");
    EXPECT_NE(take.detailText().find("object=loco loco=\"003 131-0\""), std::string::npos)
        << take.detailText();
    EXPECT_NE(take.json().find("\"object\":\"loco\",\"loco\":\"003 131-0\""), std::string::npos)
        << take.json();
    EXPECT_EQ(FrameDescription(frame(92), Station).detailText().find("object="), std::string::npos)
        << "without the context the handle is not known";
}

// Status and function frames have the same shape; only the handle learnt from the SY answer (#30) tells.
TEST_F(BusContextTrace, StatusFramesAreToldFromFunctionFramesByTheirHandle) {
    BusContext context;
    const std::vector<FrameDescription> read = readAll(frames, context);
    EXPECT_EQ(read.at(30).name(), "mcan.status-query");
    EXPECT_EQ(read.at(31).name(), "mcan.status-type");
    EXPECT_EQ(read.at(59).name(), "mcan.function-query");
    EXPECT_EQ(FrameDescription(frame(31), Station).name(), "mcan.function-query");
    EXPECT_EQ(FrameDescription(frame(31), Station, &context).name(), "mcan.status-query");
}

TEST_F(BusContextTrace, EveryFrameOfThePairNamesTheHandheldAndItsNameOnceSent) {
    BusContext context;
    const std::vector<FrameDescription> read = readAll(frames, context);
    ASSERT_TRUE(read.at(16).handheld()); // #17, before the name was sent
    EXPECT_EQ(read.at(16).handheld()->node, 43);
    EXPECT_EQ(read.at(16).handheld()->name, "");
    ASSERT_TRUE(read.at(29).handheld()); // #30, after the name (#24-26)
    EXPECT_EQ(read.at(29).handheld()->name, "KS MS1");
    EXPECT_EQ(read.at(81).handheld()->node, 43); // #82, a poll of the slave
    EXPECT_EQ(read.at(82).handheld()->node, 43); // #83, its master's answer from node 42
    EXPECT_FALSE(read.at(2).handheld());         // #3, login stage 0: no node yet
}

// An MS2's unmarked hash with priority 0 is a CS2 frame, even when its bits look like a loco-list answer.
TEST(BusContext, ACs2FrameTeachesNothingAboutHandles) {
    BusContext context;
    const std::uint8_t answer[] = {0x80, 0x02, 0x00, 0x00, 0x00, 0x09, 0x00, 0x01};
    EXPECT_EQ(context.read(CanFrame::extendedFrame(0x000009AA, answer), Station).protocol(), Protocol::Cs2);
    const std::uint8_t take[] = {0x03, 0x00, 0x00, 0x08, 0x00, 0x01};
    const FrameDescription onHandle9 = context.read(CanFrame::extendedFrame(0x1400242B, take), Station);
    EXPECT_EQ(onHandle9.name(), "mcan.throttle");
    EXPECT_EQ(onHandle9.detailText().find("object="), std::string::npos) << onHandle9.detailText();
}

// A master that hands out ever new loco handles (or a bus of garbage) cannot make the context grow without
// bound: it keeps at most 4096 handles.
TEST(BusContext, StaysBoundedWhateverTheBusCarries) {
    BusContext context;
    for (unsigned handle = 0; handle < 5000; ++handle) {
        const std::uint8_t stackAdd[] = {
            0x80, 0x00, 0xFF, 0xFF, std::uint8_t(handle >> 8), std::uint8_t(handle),
            0x00, 0x03}; // notes B§2.2 L5, on the SY handle 3 from master node 42
        context.observe(CanFrame::extendedFrame(0x18000E2A, stackAdd));
    }
    EXPECT_EQ(context.handleRoles().size(), 4096u);
}

TEST_F(BusContextTrace, ClearForgetsWhatWasLearnt) {
    BusContext context;
    readAll(frames, context);
    context.clear();
    EXPECT_EQ(FrameDescription(frame(31), Station, &context).name(), "mcan.function-query");
    EXPECT_EQ(FrameDescription(frame(30), Station, &context).handheld()->name, "");
}

} // namespace stellwerk::busreading::test
