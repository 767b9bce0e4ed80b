// Chapter 11 of the M-CAN document ("Telegramm Trace"): an MS1 plugged into a running ECoS 3.0.1. Both
// extractions of the document are read in place; each frame must decode to what the notes (B§4.2) say it
// means, the handle roles must be learnt from the answers, and every frame must encode back to itself.

#include "SeedTrace.h"
#include "mcan/Codec.h"
#include "mcan/FrameReport.h"
#include "mcan/HandleRoles.h"

#include <gtest/gtest.h>
#include <string_view>
#include <vector>

using namespace stellwerk;

namespace {

// The meaning of each of the 99 frames of [002], in order (B§4.2). "" = E-CAN/ECoSlink, not M-CAN.
const std::vector<std::string_view> TraceNames = {
    "",
    "mcan.unknown",
    "mcan.login-request",
    "mcan.login-reply",
    "mcan.login-request",
    "mcan.login-reply",
    "mcan.login-request",
    "mcan.login-reply",
    "mcan.login-request",
    "mcan.login-reply",
    "mcan.login-details",
    "mcan.login-details",
    "mcan.login-details",
    "mcan.login-details",
    "mcan.poll-answer",
    "mcan.login-grant",
    "mcan.sd-handle-request",
    "mcan.sd-handle-answer",
    "mcan.stack-size-request",
    "mcan.name-request",
    "mcan.name-request",
    "mcan.name-request",
    "mcan.stack-size-answer",
    "mcan.name-segment",
    "mcan.name-segment",
    "mcan.name-segment",
    "mcan.sy-handle-request",
    "mcan.name-request",
    "mcan.name-segment",
    "mcan.sy-handle-answer",
    "mcan.status-query",
    "mcan.status-type",
    "mcan.status-query",
    "mcan.status-value",
    "mcan.status-query",
    "mcan.status-type",
    "mcan.status-query",
    "mcan.status-value",
    "mcan.status-query",
    "mcan.status-type",
    "mcan.status-query",
    "mcan.status-value",
    "mcan.status-query",
    "mcan.status-list-end",
    "mcan.loco-list-query",
    "mcan.loco-list-answer",
    "mcan.loco-list-query",
    "mcan.loco-query",
    "mcan.loco-list-end",
    "mcan.loco-answer",
    "mcan.loco-list-query",
    "mcan.loco-query",
    "mcan.loco-list-end",
    "mcan.loco-answer",
    "mcan.loco-list-query",
    "mcan.loco-query",
    "mcan.loco-list-end",
    "",
    "mcan.loco-answer",
    "mcan.function-query",
    "mcan.function-description",
    "mcan.function-query",
    "mcan.function-value",
    "mcan.function-query",
    "mcan.function-list-end",
    "mcan.function-extra-query",
    "mcan.function-extra-answer",
    "mcan.function-extra-query",
    "mcan.function-extra-answer",
    "mcan.function-extra-query",
    "mcan.function-extra-answer",
    "mcan.loco-query",
    "mcan.loco-answer",
    "mcan.assignment-query",
    "mcan.throttle",
    "mcan.name-request",
    "mcan.name-segment",
    "mcan.name-request",
    "mcan.name-segment",
    "mcan.name-request",
    "mcan.name-segment",
    "mcan.poll",
    "mcan.poll-answer",
    "mcan.poll",
    "mcan.poll-answer",
    "mcan.poll",
    "mcan.poll-answer",
    "mcan.poll",
    "mcan.poll-answer",
    "mcan.poll",
    "mcan.poll-answer",
    "mcan.throttle",
    "mcan.throttle",
    "mcan.poll",
    "mcan.poll-answer",
    "",
    "",
    "mcan.unknown",
    "mcan.poll",
};

// The names of a trace decoded in bus order with the handle roles it reveals; "" for frames that are not
// M-CAN on a bus shared with the CS2 protocol.
std::vector<std::string_view> namesOf(const std::vector<can::CanFrame>& frames) {
    mcan::HandleRoles roles;
    std::vector<std::string_view> names;
    for (const can::CanFrame& frame : frames)
        names.push_back(mcan::isMcan(frame) ? mcan::nameOf(roles.observe(frame)) : std::string_view());
    return names;
}

template <class T>
T messageAt(const std::vector<can::CanFrame>& frames, std::size_t number) {
    mcan::HandleRoles roles;
    for (std::size_t i = 0; i + 1 < number; ++i)
        roles.observe(frames[i]);
    const mcan::Message message = roles.decode(frames[number - 1]);
    EXPECT_TRUE(std::holds_alternative<T>(message)) << "frame #" << number << " is " << mcan::nameOf(message);
    return std::holds_alternative<T>(message) ? std::get<T>(message) : T{};
}

} // namespace

TEST(McanTrace, Document002HasAllNinetyNineFramesWithTheNotesMeanings) {
    const std::vector<can::CanFrame> frames = seeds::chapter11Trace(seeds::McanSeed002);
    ASSERT_EQ(frames.size(), 99u);
    const std::vector<std::string_view> names = namesOf(frames);
    for (std::size_t i = 0; i < frames.size(); ++i)
        EXPECT_EQ(names[i], TraceNames[i]) << "frame #" << i + 1;
}

TEST(McanTrace, Document000LacksOnePollPairAndOtherwiseReadsTheSame) {
    const std::vector<can::CanFrame> frames = seeds::chapter11Trace(seeds::McanSeed000);
    ASSERT_EQ(frames.size(), 97u);
    std::vector<std::string_view> expected = TraceNames;
    expected.erase(expected.begin() + 89, expected.begin() + 91); // #90 and #91 (notes X1)
    const std::vector<std::string_view> names = namesOf(frames);
    for (std::size_t i = 0; i < frames.size(); ++i)
        EXPECT_EQ(names[i], expected[i]) << "frame #" << i + 1;
    const std::vector<can::CanFrame> full = seeds::chapter11Trace(seeds::McanSeed002);
    for (std::size_t i = 0; i < frames.size(); ++i)
        EXPECT_EQ(frames[i], full[i < 89 ? i : i + 2]) << "frame #" << i + 1;
}

TEST(McanTrace, EveryFrameEncodesBackToItself) {
    for (const auto& seed : {seeds::McanSeed000, seeds::McanSeed002}) {
        mcan::HandleRoles roles;
        for (const can::CanFrame& frame : seeds::chapter11Trace(seed))
            EXPECT_EQ(mcan::encode(roles.observe(frame)), frame)
                << seed << ": " << mcan::FrameReport(frame).text();
    }
}

TEST(McanTrace, LoginStagesCarryTheUidBytesAndTheMid) {
    const auto frames = seeds::chapter11Trace(seeds::McanSeed002);
    const auto stage0 = messageAt<mcan::LoginRequest>(frames, 3);
    EXPECT_EQ(stage0.stage, 0);
    EXPECT_EQ(stage0.uidByte, 0x00);
    EXPECT_EQ(stage0.mid, 0);
    const auto reply0 = messageAt<mcan::LoginReply>(frames, 4);
    EXPECT_EQ(reply0.mid, 12);
    EXPECT_EQ(reply0.data[1], 0x04); // master UID 0x000484D3
    const auto stage3 = messageAt<mcan::LoginRequest>(frames, 9);
    EXPECT_EQ(stage3.stage, 3);
    EXPECT_EQ(stage3.uidByte, 0xB3);
    EXPECT_EQ(stage3.mid, 12);
    const auto stage4 = messageAt<mcan::LoginDetails>(frames, 11);
    EXPECT_EQ(stage4.stage, 4);
    EXPECT_EQ(stage4.data[3], 0xB3); // UID 0x000204B3
}

TEST(McanTrace, StageSevenReplyGivesNode43StartHandle2AndNoFlashMode) {
    const auto grant = messageAt<mcan::LoginGrant>(seeds::chapter11Trace(seeds::McanSeed002), 16);
    EXPECT_EQ(grant.slaveUid, 0x000204B3u);
    EXPECT_EQ(grant.startHandle, 0x0002);
    EXPECT_EQ(grant.node, 43);
    EXPECT_TRUE(grant.multiSlave);
    EXPECT_EQ(grant.flags, 0);
}

TEST(McanTrace, HandlesAreLearntFromTheAnswers) {
    const auto frames = seeds::chapter11Trace(seeds::McanSeed002);
    mcan::HandleRoles roles;
    for (const can::CanFrame& frame : frames)
        roles.observe(frame);
    EXPECT_EQ(roles.role(43, 0x0002), mcan::HandleRole::Start);
    EXPECT_EQ(roles.role(43, 0x0008), mcan::HandleRole::SlaveDescription);
    EXPECT_EQ(roles.role(43, 0x0003), mcan::HandleRole::SystemStatus);
    EXPECT_EQ(roles.role(43, 0x0009), mcan::HandleRole::Loco);
    EXPECT_EQ(roles.role(43, 0x0001), mcan::HandleRole::Poll);
    EXPECT_EQ(roles.name(43, 0x0009), "003 131-0");
    EXPECT_EQ(roles.slaveName(43), "KS MS1");
}

TEST(McanTrace, TheMonitorNamesALocomotiveHandleWithItsName) {
    const auto frames = seeds::chapter11Trace(seeds::McanSeed002);
    mcan::HandleRoles roles;
    for (std::size_t i = 0; i < 91; ++i)
        roles.observe(frames[i]);
    const mcan::FrameReport take(frames[91], &roles); // #92: the slave takes the loco
    EXPECT_EQ(take.name(), "mcan.throttle");
    EXPECT_NE(take.detailText().find("object=loco loco=\"003 131-0\""), std::string::npos)
        << take.detailText();
    EXPECT_NE(take.detailText().find("from=slave node=43 handle=0x0009 prio=5"), std::string::npos);
}

TEST(McanTrace, StatusAndFunctionFramesAreToldApartByTheirHandle) {
    const auto frames = seeds::chapter11Trace(seeds::McanSeed002);
    const auto stop = messageAt<mcan::StatusType>(frames, 32);
    EXPECT_EQ(stop.index, 1);
    EXPECT_EQ(stop.type, 1); // stop/go
    const auto value = messageAt<mcan::StatusValue>(frames, 34);
    EXPECT_EQ(value.at.prio, mcan::prio::Status);
    const auto speed = messageAt<mcan::FunctionDescription>(frames, 61);
    EXPECT_EQ(speed.function, 1);
    EXPECT_EQ(speed.kind, 1);
    EXPECT_EQ(speed.icon, 1);
    // Without the roles, the same status query on the SY handle reads as a function query.
    EXPECT_TRUE(std::holds_alternative<mcan::FunctionQuery>(mcan::decode(frames[30])));
}

TEST(McanTrace, PollAnswersCarryTheMasterNodeAndUid) {
    const auto frames = seeds::chapter11Trace(seeds::McanSeed002);
    const auto poll = messageAt<mcan::Poll>(frames, 82);
    EXPECT_EQ(poll.masterNode, 42);
    EXPECT_EQ(poll.at.handle, 0x0001);
    const auto answer = messageAt<mcan::PollAnswer>(frames, 83);
    EXPECT_EQ(answer.aboutNode, 42);
    EXPECT_EQ(answer.uid, 0x000484D3u);
}
