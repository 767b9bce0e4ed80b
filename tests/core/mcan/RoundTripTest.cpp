// Every M-CAN message encodes to a frame that decodes back to the same message and the same bytes, and
// frames the documents do not explain decode as mcan.unknown with their fields, never as something else.

#include "mcan/Codec.h"
#include "mcan/FrameReport.h"

#include <gtest/gtest.h>
#include <string_view>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::mcan;

namespace {

constexpr std::uint8_t Slave = 43;
constexpr std::uint8_t Master = 42;

Address slave(std::uint16_t handle, std::uint8_t priority = prio::Data) {
    return {priority, handle, Slave};
}
Address master(std::uint16_t handle, std::uint8_t priority = prio::Data) {
    return {priority, handle, Master};
}

struct Sample {
    Message message;
    HandleRole role = HandleRole::Unknown;
};

// One message of every kind, from the side that sends it, with values from the trace and the tables.
std::vector<Sample> samples() {
    return {
        {LoginRequest{2, 0x04, 12}},
        {LoginReply{0, 0x00, 12, {0x00, 0x04, 0x84, 0xD3, 0x00, 0x01, 0x00, 0x01}}},
        {LoginDetails{4, 12, {0x00, 0x02, 0x04, 0xB3, 0x00, 0x02, 0x00, 0x03}}},
        {LoginGrant{12, 0x000204B3, 0x0002, 43, true, 0}},
        {BusBusy{8}},
        {SdHandleRequest{slave(2), Slave}},
        {SdHandleAnswer{master(2), Slave, 0x0008}},
        {StackSizeRequest{master(8)}},
        {StackSizeAnswer{slave(8), 10}},
        {NameRequest{master(8), 4}},
        {NameSegment{slave(8), 4, 3, {'S', '1', '\0', '\0'}, 0}},
        {SyHandleRequest{slave(2)}},
        {SyHandleAnswer{master(2), 0x0003, 0x03, 0x00}},
        {StatusQuery{slave(3), 2, true}, HandleRole::SystemStatus},
        {StatusType{master(3), 2, 2}, HandleRole::SystemStatus},
        {StatusListEnd{master(3), 4}, HandleRole::SystemStatus},
        {StatusValue{master(3, prio::Status), 1, 1}, HandleRole::SystemStatus},
        {LocoListQuery{slave(2), 0x80, 0x0009}},
        {LocoListAnswer{master(2), 0x80, 0x0000, 0x0009}},
        {LocoListEnd{master(2), 0x81, 0x0000}},
        {StackAdd{master(3), 0x000A}},
        {StackDelete{master(3), 0x000A}},
        {LocoQuery{slave(9), 0x01, 1}},
        {LocoAnswer{master(9), 0x03, 0, {2, {0x00, 0x03}}}},
        {FunctionQuery{slave(9), 3, false}, HandleRole::Loco},
        {FunctionDescription{master(9), 3, 2, 0x0B}, HandleRole::Loco},
        {FunctionListEnd{master(9), 10}, HandleRole::Loco},
        {FunctionValue{slave(9, prio::SlaveDrive), 1, 0x85}, HandleRole::Loco},
        {FunctionExtraQuery{slave(9), 2}},
        {FunctionExtraAnswer{master(9), 2, 0}},
        {AssignmentQuery{slave(9)}},
        {Throttle{slave(9, prio::Throttle), 1, 0x0008, 1}},
        {Poll{slave(1, prio::Master), Master}},
        {PollAnswer{master(1, prio::Master), 0x00, Master, 0x000484D3}},
        {MasterPoll{master(1, prio::Master), Master}},
        {PollReply{slave(1, prio::Master), 0x000204B3}},
        {FlashReady{0x000204B3}},
        {FlashQuery{2, 3, 0x000204B3}},
        {FlashAnswer{2, 2, 0x000204B3, 0x01004010}},
        {FlashStart{0, 0x000204B3}},
        {FlashDataRequest{2, 0x0226, 0x0226}},
        {FlashData{2, 0x0000, 2, {0xEC, 0xFB, 0, 0}}},
        {FlashEnd{2, 0x000204B3}},
    };
}

} // namespace

TEST(McanRoundTrip, EveryKindOfMessageIsSampled) {
    std::vector<bool> seen(std::variant_size_v<Message>);
    for (const Sample& sample : samples())
        seen[sample.message.index()] = true;
    for (std::size_t i = 0; i + 1 < seen.size(); ++i) // all but Unknown
        EXPECT_TRUE(seen[i]) << "no sample of alternative " << i;
}

// The names a monitor offers in its command filter: one per kind of message, each the name it decodes to.
TEST(McanRoundTrip, EveryKindOfMessageHasItsNameInTheList) {
    const std::vector<std::string_view> names = messageNames();
    ASSERT_EQ(names.size(), std::variant_size_v<Message>);
    for (const Sample& sample : samples())
        EXPECT_EQ(names[sample.message.index()], nameOf(sample.message));
    EXPECT_EQ(names.back(), "mcan.unknown");
}

TEST(McanRoundTrip, EveryMessageDecodesToItselfAndItsBytes) {
    for (const Sample& sample : samples()) {
        const can::CanFrame frame = encode(sample.message);
        EXPECT_TRUE(isMcan(frame)) << nameOf(sample.message);
        const Message back = decode(frame, sample.role);
        EXPECT_EQ(nameOf(back), nameOf(sample.message)) << FrameReport(frame).text();
        EXPECT_EQ(encode(back), frame) << nameOf(sample.message);
        EXPECT_EQ(describe(back).size(), describe(sample.message).size()) << nameOf(sample.message);
    }
}

TEST(McanRoundTrip, FramesOfNoDocumentedFormAreUnknownWithTheirFields) {
    // A slave answering a stack-size request with the master's DLC, and a login stage 2 carrying data.
    const can::CanFrame wrongSide = encode(StackSizeRequest{slave(8)});
    const can::CanFrame loginWithData =
        can::CanFrame::extendedFrame(loginId({0x04, 2, 12, false}), std::vector<std::uint8_t>{1, 2});
    for (const can::CanFrame& frame : {wrongSide, loginWithData}) {
        const FrameReport report(frame);
        EXPECT_EQ(report.name(), "mcan.unknown");
        EXPECT_FALSE(report.decoded());
        EXPECT_NE(report.detailText().find("why="), std::string::npos) << report.detailText();
        EXPECT_EQ(encode(report.message()), frame);
    }
}

TEST(McanRoundTrip, ANameFromTheBusCannotPutControlCharactersIntoATerminal) {
    const NameSegment hostile{slave(8), 0, 4, {'\x1b', '[', '2', 'J'}, 0};
    const FrameReport report(encode(hostile));
    EXPECT_NE(report.detailText().find("chars=\\x1B[2J"), std::string::npos) << report.detailText();
    for (const char c : report.text() + report.json())
        EXPECT_TRUE(c >= 0x20 && c < 0x7F) << int(c);
}

TEST(McanClassifier, SeparatesMcanFromCs2AsTheNotesSay) {
    EXPECT_FALSE(isMcanId(0x0C084B11)); // prio bits set, but the CS2 marker (bits 9..7 = 110)
    EXPECT_FALSE(isMcanId(0x00084711)); // priority 0 without the marker: a CS2 sender
    EXPECT_TRUE(isMcanId(BusBusyId));
    EXPECT_TRUE(isMcanId(0x0C0007AB));  // trace #82, a poll
    EXPECT_TRUE(isMcanId(0x1C00007E));  // trace #3, login stage 0
    EXPECT_FALSE(isMcanId(0x1C00037E)); // priority 111 but the CS2 marker: a CS2 frame
    EXPECT_EQ(layoutOf(0x1C00007E), Layout::Login);
    EXPECT_EQ(layoutOf(0x1C0800FF), Layout::Flash);
    EXPECT_EQ(layoutOf(0x0C0007AB), Layout::Session);
    EXPECT_FALSE(isMcan(can::CanFrame::standard(0x380, {})));
}
