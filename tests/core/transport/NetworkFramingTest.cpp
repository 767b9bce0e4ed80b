// The 13-byte network form (field notes, "Framing"): id big endian, DLC, data padded with zeros; UDP
// datagrams of n x 13 bytes.

#include "transport/NetworkFraming.h"

#include "TestSupport.h"

namespace stellwerk::transport::test {
namespace {

std::vector<std::uint8_t> bytesOf(const QByteArray& bytes) {
    return {bytes.begin(), bytes.end()};
}

// System stop as the document's example writes it: 00004711 5 00 00 00 00 00.
TEST(NetworkFraming, SystemStopIsThirteenBytesPaddedWithZeros) {
    const QByteArray bytes = encodeFrames(std::vector{frame(0x00004711, {0, 0, 0, 0, 0})});
    const std::vector<std::uint8_t> expected{0x00, 0x00, 0x47, 0x11, 0x05, 0, 0, 0, 0, 0, 0, 0, 0};
    EXPECT_EQ(bytesOf(bytes), expected);
}

TEST(NetworkFraming, SeveralFramesFollowEachOther) {
    const auto frames = numberedFrames(3);
    const QByteArray bytes = encodeFrames(frames);
    ASSERT_EQ(bytes.size(), 39);
    std::vector<CanFrame> decoded;
    const DatagramContent content = decodeDatagram(asBytes(bytes), decoded);
    EXPECT_TRUE(content.wholeFrames);
    EXPECT_EQ(content.frames, 3u);
    EXPECT_EQ(content.malformed, 0u);
    EXPECT_EQ(decoded, frames);
}

TEST(NetworkFraming, DatagramThatIsNotAMultipleOf13BytesGivesNothing) {
    for (const int size : {0, 1, 12, 14, 25, 27}) {
        const QByteArray datagram(size, '\0');
        std::vector<CanFrame> decoded;
        const DatagramContent content = decodeDatagram(asBytes(datagram), decoded);
        EXPECT_FALSE(content.wholeFrames) << size;
        EXPECT_TRUE(decoded.empty()) << size;
    }
}

TEST(NetworkFraming, DatagramFrameWithDlcAboveEightIsLeftOutAndCounted) {
    QByteArray datagram = encodeFrames(numberedFrames(3));
    datagram[13 + 4] = char(9);
    std::vector<CanFrame> decoded;
    const DatagramContent content = decodeDatagram(asBytes(datagram), decoded);
    EXPECT_TRUE(content.wholeFrames);
    EXPECT_EQ(content.frames, 2u);
    EXPECT_EQ(content.malformed, 1u);
    EXPECT_EQ(decoded, (std::vector{numbered(0), numbered(2)}));
}

TEST(NetworkFraming, IdBitsAbove29AreMalformed) {
    QByteArray datagram = encodeFrames(numberedFrames(1));
    datagram[0] = char(0x20);
    std::vector<CanFrame> decoded;
    EXPECT_EQ(decodeDatagram(asBytes(datagram), decoded).malformed, 1u);
    EXPECT_TRUE(decoded.empty());
}

} // namespace
} // namespace stellwerk::transport::test
