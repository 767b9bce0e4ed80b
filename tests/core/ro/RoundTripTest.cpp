// Every request kind (004 §3.2.1, §3.2.2: eight COMMANDs) and every answer kind (§3.5: OK, 0xFD, 0xFE)
// decodes back to itself after encoding, at the edges of their fields.
#include "ro/Codec.h"
#include "ro/RoProfile.h"

#include <gtest/gtest.h>

namespace stellwerk::ro {
namespace {

constexpr Width AllWidths[] = {Width::Bit, Width::Byte, Width::Word, Width::Long};

TEST(RoRoundTrip, EveryRequestCommand) {
    int commands = 0;
    for (const auto kind : {Request::Kind::Write, Request::Kind::Read})
        for (const Width width : AllWidths)
            for (const std::uint16_t address : {0x0000, 0x0012, 0xFFFF})
                for (const std::uint8_t job : {0x00, 0x34, 0xFF}) {
                    const std::uint32_t value = kind == Request::Kind::Write ? maxValue(width) : 0;
                    const Request request{kind, width, address, job, value};
                    for (const auto size : {ReadRequestSize::Eight, ReadRequestSize::Four}) {
                        const Payload payload = encode(request, size);
                        const auto decoded = decodeRequest(payload.span());
                        ASSERT_TRUE(decoded) << request.name() << ": " << decoded.error().reason;
                        EXPECT_EQ(*decoded, request) << request.name();
                        EXPECT_EQ(decoded->command(), payload.bytes[0]);
                    }
                    commands += address == 0 && job == 0;
                }
    EXPECT_EQ(commands, 8);
}

TEST(RoRoundTrip, WriteCommandsAreEightBytesAndReadsFollowTheProfile) {
    for (const Width width : AllWidths) {
        EXPECT_EQ(encode(Request{Request::Kind::Write, width}).size, 8);
        EXPECT_EQ(encode(Request{Request::Kind::Read, width}).size, 8);
        EXPECT_EQ(encode(Request{Request::Kind::Read, width}, ReadRequestSize::Four).size, 4);
    }
}

TEST(RoRoundTrip, EveryAnswer) {
    std::vector<Answer> answers{InvalidCommandAnswer{}};
    for (const Width width : {Width::None, Width::Bit, Width::Byte, Width::Word, Width::Long})
        answers.push_back(OkAnswer{width, 0xA5, maxValue(width)});
    for (std::uint8_t dataBytes = 0; dataBytes <= 4; ++dataBytes)
        answers.push_back(
            DuplicateJobAnswer{0x7F, dataBytes, dataBytes ? 0xFFFFFFFFu >> (32 - 8 * dataBytes) : 0u});
    for (const Answer& answer : answers) {
        const auto decoded = decodeAnswer(encode(answer).span());
        ASSERT_TRUE(decoded) << nameOf(answer) << ": " << decoded.error().reason;
        EXPECT_EQ(*decoded, answer) << nameOf(answer);
    }
}

TEST(RoRoundTrip, FramesOfAModuleCarryItsIdsAndFormat) {
    RoProfile profile = RoProfile::simulator(3);
    const Request request{Request::Kind::Write, Width::Word, 0, 0x35, 0x2000};
    const can::CanFrame frame = profile.requestFrame(request);
    EXPECT_EQ(frame.id, 0x01FE0003u);
    EXPECT_TRUE(frame.extended);
    EXPECT_EQ(directionOf(frame, profile.ids), Direction::Request);
    EXPECT_EQ(decodeRequest(frame.payload()).value(), request);

    profile.ids = {0x123, 0x124, false};
    const can::CanFrame answer = profile.answerFrame(OkAnswer{Width::None, 0x35});
    EXPECT_EQ(answer.id, 0x124u);
    EXPECT_FALSE(answer.extended);
    EXPECT_EQ(answer.dlc, 7);
    EXPECT_EQ(directionOf(answer, profile.ids), Direction::Answer);
    // The same id in the other frame format is not this module's.
    can::CanFrame extended = answer;
    extended.extended = true;
    EXPECT_EQ(directionOf(extended, profile.ids), std::nullopt);
}

} // namespace
} // namespace stellwerk::ro
