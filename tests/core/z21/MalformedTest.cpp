// Datagrams a server must survive: wrong XOR bytes (answered, but flagged), wrong lengths, cut and
// garbage datagrams (errors that keep the requests before them), values the specification does not allow.
#include "Z21TestSupport.h"

using namespace stellwerk::z21;
using namespace stellwerk::z21::test;

TEST(Z21Malformed, WrongXorIsReadAndFlagged) {
    const Request request = onlyRequest({0x07, 0x00, 0x40, 0x00, 0x21, 0x81, 0x00});
    EXPECT_TRUE(std::holds_alternative<SetTrackPowerOn>(request.body));
    EXPECT_TRUE(request.wrongChecksum);
}

TEST(Z21Malformed, DataLenBelowFourStopsTheDatagram) {
    const DatagramRequests read =
        readRequests(Bytes{0x04, 0x00, 0x10, 0x00, 0x02, 0x00, 0x10, 0x00, 0x04, 0x00});
    ASSERT_EQ(read.requests.size(), 1u);
    ASSERT_EQ(read.errors.size(), 1u);
    EXPECT_EQ(read.errors[0].problem, PacketProblem::LengthBelowFour);
    EXPECT_EQ(read.errors[0].offset, 4u);
}

TEST(Z21Malformed, DataLenBeyondTheDatagramIsTruncated) {
    const DatagramRequests read = readRequests(Bytes{0x0A, 0x00, 0x40, 0x00, 0xE4, 0x13, 0x00});
    EXPECT_TRUE(read.requests.empty());
    ASSERT_EQ(read.errors.size(), 1u);
    EXPECT_EQ(read.errors[0].problem, PacketProblem::Truncated);
}

TEST(Z21Malformed, BytesAfterTheLastPacketAreTruncated) {
    const DatagramRequests read = readRequests(Bytes{0x04, 0x00, 0x51, 0x00, 0x04, 0x00});
    EXPECT_EQ(read.requests.size(), 1u);
    ASSERT_EQ(read.errors.size(), 1u);
    EXPECT_EQ(read.errors[0].problem, PacketProblem::Truncated);
    EXPECT_EQ(read.errors[0].offset, 4u);
}

TEST(Z21Malformed, KnownCommandOfWrongLengthIsAnErrorAndTheNextPacketIsRead) {
    const DatagramRequests read = readRequests(Bytes{0x05, 0x00, 0x10, 0x00, 0x00, 0x09, 0x00, 0x40, 0x00,
                                                     0xE4, 0x13, 0x00, 0x03, 0x76, 0x04, 0x00, 0x30, 0x00});
    ASSERT_EQ(read.errors.size(), 2u);
    EXPECT_EQ(read.errors[0].problem, PacketProblem::WrongLength);
    EXPECT_EQ(read.errors[0].header, 0x10);
    EXPECT_EQ(read.errors[1].problem, PacketProblem::WrongLength);
    EXPECT_EQ(read.errors[1].offset, 5u);
    ASSERT_EQ(read.requests.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<Logoff>(read.requests[0].body));
}

TEST(Z21Malformed, XBusPacketWithoutChecksumByteIsWrongLength) {
    const DatagramRequests read = readRequests(Bytes{0x05, 0x00, 0x40, 0x00, 0x80});
    ASSERT_EQ(read.errors.size(), 1u);
    EXPECT_EQ(read.errors[0].problem, PacketProblem::WrongLength);
}

TEST(Z21Malformed, UnknownHeadersAndXHeadersAreUnknownRequests) {
    EXPECT_EQ(std::get<UnknownRequest>(onlyRequest({0x05, 0x00, 0x81, 0x00, 0x00}).body).header, 0x81);
    // LAN_X_SET_LOCO_FUNCTION_GROUP (4.3.2) and LAN_X_CV_READ (6.1) are not read.
    const Request group = onlyRequest({0x0A, 0x00, 0x40, 0x00, 0xE4, 0x20, 0x00, 0x03, 0x10, 0xD7});
    EXPECT_EQ(std::get<UnknownRequest>(group.body).data, (Bytes{0xE4, 0x20, 0x00, 0x03, 0x10, 0xD7}));
    EXPECT_TRUE(std::holds_alternative<UnknownRequest>(
        onlyRequest({0x09, 0x00, 0x40, 0x00, 0x23, 0x11, 0x00, 0x1C, 0x2E}).body));
}

TEST(Z21Malformed, ValuesTheSpecificationForbidsAreUnknown) {
    // TT = 11 "not allowed", F32 above F31, loco mode 2, a 0x1S with S = 1.
    EXPECT_TRUE(std::holds_alternative<UnknownRequest>(
        onlyRequest({0x0A, 0x00, 0x40, 0x00, 0xE4, 0xF8, 0x00, 0x03, 0xC1, 0xDE}).body));
    EXPECT_TRUE(std::holds_alternative<UnknownRequest>(
        onlyRequest({0x0A, 0x00, 0x40, 0x00, 0xE4, 0xF8, 0x00, 0x03, 0x20, 0x3F}).body));
    EXPECT_TRUE(
        std::holds_alternative<UnknownRequest>(onlyRequest({0x07, 0x00, 0x61, 0x00, 0x00, 0x03, 0x02}).body));
    EXPECT_TRUE(std::holds_alternative<UnknownRequest>(
        onlyRequest({0x0A, 0x00, 0x40, 0x00, 0xE4, 0x11, 0x00, 0x03, 0x82, 0x74}).body));
}

TEST(Z21Malformed, UnknownDataIsKeptUpTo64Bytes) {
    Bytes datagram{0x68, 0x00, 0x99, 0x00};
    datagram.resize(0x68, 0xAA);
    EXPECT_EQ(std::get<UnknownRequest>(onlyRequest(datagram).body).data.size(), 64u);
}

TEST(Z21Malformed, EmptyAndGarbageDatagrams) {
    EXPECT_TRUE(readRequests(Bytes{}).requests.empty());
    EXPECT_TRUE(readRequests(Bytes{}).errors.empty());
    const DatagramRequests garbage = readRequests(Bytes{0xFF, 0xFF, 0xFF, 0xFF, 0x01});
    EXPECT_TRUE(garbage.requests.empty());
    ASSERT_EQ(garbage.errors.size(), 1u);
    EXPECT_EQ(garbage.errors[0].problem, PacketProblem::Truncated);
}

TEST(Z21Malformed, RepliesThatAreNoneAreErrors) {
    const DatagramReplies read =
        readReplies(Bytes{0x05, 0x00, 0x18, 0x00, 0x00, 0x07, 0x00, 0x40, 0x00, 0x61, 0x55, 0x34});
    ASSERT_EQ(read.replies.size(), 1u);
    ASSERT_EQ(read.errors.size(), 1u);
    EXPECT_EQ(read.errors[0].problem, PacketProblem::NotAReply);
}
