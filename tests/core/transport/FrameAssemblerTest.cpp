// TCP carries 13-byte frames "split and joined arbitrarily across segments" (field notes, "Framing").

#include "transport/FrameAssembler.h"

#include "TestSupport.h"
#include "transport/NetworkFraming.h"

#include <random>

namespace stellwerk::transport::test {
namespace {

std::span<const std::uint8_t> slice(const QByteArray& bytes, std::size_t from, std::size_t count) {
    return asBytes(bytes).subspan(from, count);
}

TEST(FrameAssembler, WholeFramesInOneReadComeOutInOrder) {
    const auto frames = numberedFrames(10);
    FrameAssembler assembler;
    std::vector<CanFrame> out;
    EXPECT_EQ(assembler.feed(asBytes(encodeFrames(frames)), out), 0u);
    EXPECT_EQ(out, frames);
    EXPECT_EQ(assembler.pendingBytes(), 0u);
}

TEST(FrameAssembler, FrameFedByteByByteComesOutWithItsLastByte) {
    const QByteArray bytes = encodeFrames(std::vector{numbered(7)});
    FrameAssembler assembler;
    std::vector<CanFrame> out;
    for (std::size_t i = 0; i < 12; ++i) {
        assembler.feed(slice(bytes, i, 1), out);
        EXPECT_TRUE(out.empty()) << "after byte " << i;
        EXPECT_EQ(assembler.pendingBytes(), i + 1);
    }
    assembler.feed(slice(bytes, 12, 1), out);
    EXPECT_EQ(out, std::vector{numbered(7)});
    EXPECT_EQ(assembler.pendingBytes(), 0u);
}

TEST(FrameAssembler, StreamFedByteByByteKeepsEveryFrame) {
    const auto frames = numberedFrames(20);
    const QByteArray bytes = encodeFrames(frames);
    FrameAssembler assembler;
    std::vector<CanFrame> out;
    for (qsizetype i = 0; i < bytes.size(); ++i)
        assembler.feed(slice(bytes, std::size_t(i), 1), out);
    EXPECT_EQ(out, frames);
}

TEST(FrameAssembler, RandomSplitsKeepEveryFrameInOrder) {
    const auto frames = numberedFrames(200);
    const QByteArray bytes = encodeFrames(frames);
    for (unsigned seed = 1; seed <= 100; ++seed) {
        std::mt19937 random(seed);
        std::uniform_int_distribution<std::size_t> segment(0, 40);
        FrameAssembler assembler;
        std::vector<CanFrame> out;
        for (std::size_t at = 0; at < std::size_t(bytes.size());) {
            const std::size_t count = std::min(segment(random), std::size_t(bytes.size()) - at);
            EXPECT_EQ(assembler.feed(slice(bytes, at, count), out), 0u);
            at += count;
        }
        ASSERT_EQ(out, frames) << "seed " << seed;
        EXPECT_EQ(assembler.pendingBytes(), 0u);
    }
}

TEST(FrameAssembler, DlcAboveEightIsCountedAndTheStreamGoesOn) {
    QByteArray bytes = encodeFrames(numberedFrames(3));
    bytes[13 + 4] = char(12);
    FrameAssembler assembler;
    std::vector<CanFrame> out;
    EXPECT_EQ(assembler.feed(slice(bytes, 0, 20), out), 0u);
    EXPECT_EQ(assembler.feed(slice(bytes, 20, 19), out), 1u);
    EXPECT_EQ(out, (std::vector{numbered(0), numbered(2)}));
}

TEST(FrameAssembler, ClearForgetsAPartialFrame) {
    const QByteArray bytes = encodeFrames(numberedFrames(2));
    FrameAssembler assembler;
    std::vector<CanFrame> out;
    assembler.feed(slice(bytes, 0, 5), out);
    EXPECT_EQ(assembler.pendingBytes(), 5u);
    assembler.clear();
    assembler.feed(slice(bytes, 13, 13), out);
    EXPECT_EQ(out, std::vector{numbered(1)});
}

} // namespace
} // namespace stellwerk::transport::test
