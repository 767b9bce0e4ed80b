// Payloads that are no RO message are refused with the reason and the byte (1-based, as 004 counts).
#include "ro/Codec.h"

#include <gtest/gtest.h>
#include <vector>

namespace stellwerk::ro {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::string requestError(const Bytes& bytes) {
    const auto decoded = decodeRequest(bytes);
    return decoded ? std::string("decoded") : decoded.error().reason;
}

std::string answerError(const Bytes& bytes) {
    const auto decoded = decodeAnswer(bytes);
    return decoded ? std::string("decoded") : decoded.error().reason;
}

TEST(RoMalformed, RequestsAreRefusedWithAReason) {
    EXPECT_EQ(requestError({}), "empty payload");
    EXPECT_EQ(requestError({0x10, 0, 0, 1, 0, 0, 0, 0}),
              "COMMAND 0x10 is none of 0x11-0x14, 0x21-0x24 (004 §3.2.1, §3.2.2)");
    EXPECT_EQ(requestError({0x15, 0, 0, 1, 0, 0, 0, 0}),
              "COMMAND 0x15 is none of 0x11-0x14, 0x21-0x24 (004 §3.2.1, §3.2.2)");
    EXPECT_EQ(requestError({0x01, 0, 0, 1}),
              "COMMAND 0x01 is none of 0x11-0x14, 0x21-0x24 (004 §3.2.1, §3.2.2)");
    EXPECT_EQ(requestError({0x23, 0, 0}),
              "a request needs at least 4 bytes (command, address, job id), got 3");
    EXPECT_EQ(requestError({0x14, 0, 0, 1, 0xAA, 0xBB}), "ro.write-long needs 8 bytes, got 6");
    EXPECT_EQ(requestError({0x12, 0x12, 0, 0x34, 0x0F, 0x01, 0, 0}), "DATA 0x10F does not fit a byte write");
    EXPECT_EQ(requestError({0x11, 0, 0, 1, 0x02, 0, 0, 0}), "DATA 0x2 does not fit a bit write");
}

TEST(RoMalformed, TheRefusedByteIsNamed) {
    EXPECT_EQ(decodeRequest(Bytes{0x30, 0, 0, 1}).error().byte, 1u);
    EXPECT_EQ(decodeRequest(Bytes{0x13, 0, 0, 1, 0}).error().byte, 6u);
    EXPECT_EQ(decodeAnswer(Bytes{0x01, 0x05, 0x34}).error().byte, 2u);
}

TEST(RoMalformed, AnswersAreRefusedWithAReason) {
    EXPECT_EQ(answerError({}), "empty payload");
    EXPECT_EQ(answerError({0x13, 0, 0, 0x35, 0, 0x20, 0, 0}),
              "answer code 0x13 is none of 0x01, 0xFD, 0xFE (004 §3.5)");
    EXPECT_EQ(answerError({0x01, 0x00}), "OK answer needs at least 3 bytes (answer, width, job id), got 2");
    EXPECT_EQ(answerError({0x01, 0x05, 0x34, 0, 0, 0, 0}), "width code 0x05 is not 0-4 (004 §3.5.1)");
    EXPECT_EQ(answerError({0x01, 0x02, 0x34, 0x00, 0x01, 0, 0}), "data does not fit a byte answer");
    EXPECT_EQ(answerError({0xFD}), "0xFD answer without job id (004 §3.5.2.1)");
    EXPECT_EQ(answerError({0xFD, 0x35, 1, 2, 3, 4, 5}), "0xFD answer carries at most 4 data bytes, got 5");
}

// Notes R7, R10: an OK of 3..7 bytes and a 0xFD with data after the job id are accepted.
TEST(RoMalformed, ShortOkAndDuplicateWithDataAreAccepted) {
    EXPECT_EQ(decodeAnswer(Bytes{0x01, 0x00, 0x34}).value(), Answer(OkAnswer{Width::None, 0x34, 0}));
    EXPECT_EQ(decodeAnswer(Bytes{0x01, 0x03, 0x36, 0x00, 0x20}).value(),
              Answer(OkAnswer{Width::Word, 0x36, 0x2000}));
    EXPECT_EQ(decodeAnswer(Bytes{0xFD, 0x36, 0x00, 0x20}).value(),
              Answer(DuplicateJobAnswer{0x36, 2, 0x2000}));
}

} // namespace
} // namespace stellwerk::ro
