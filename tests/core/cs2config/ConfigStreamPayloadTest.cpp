// The bytes inside a config-data stream: the CS2's compressed form and the MS2's padded text form.

#include "cs2config/ConfigStreamPayload.h"

#include "ConfigStreamTestSupport.h"

#include <gtest/gtest.h>
#include <zlib.h>

using namespace stellwerk::cs2config;
using test::bytesOf;

namespace {

std::vector<std::uint8_t> withPrefix(std::uint32_t size, std::vector<std::uint8_t> zlib) {
    std::vector<std::uint8_t> out{std::uint8_t(size >> 24), std::uint8_t(size >> 16), std::uint8_t(size >> 8),
                                  std::uint8_t(size)};
    out.insert(out.end(), zlib.begin(), zlib.end());
    return out;
}

// Compressed payload whose prefix announces `announced` bytes for the actual `contents`.
std::vector<std::uint8_t> lyingPayload(const std::string& contents, std::uint32_t announced) {
    auto honest = payload::compress(contents);
    honest[0] = std::uint8_t(announced >> 24), honest[1] = std::uint8_t(announced >> 16);
    honest[2] = std::uint8_t(announced >> 8), honest[3] = std::uint8_t(announced);
    return honest;
}

} // namespace

TEST(ConfigStreamPayload, CompressedFormIsSizePrefixAndZlibStream) {
    const std::string contents = "[lokomotive]\nversion\n .minor=1\n";
    const auto bytes = payload::compress(contents);
    ASSERT_GE(bytes.size(), 6u);
    EXPECT_EQ(payload::announcedSize(bytes), contents.size());
    EXPECT_EQ(bytes[4], 0x78); // zlib, default level: 78 9C
    EXPECT_EQ(bytes[5], 0x9C);
    EXPECT_TRUE(payload::isCompressed(bytes));
    EXPECT_EQ(payload::inflate(bytes, 1 << 20).value(), contents);
}

TEST(ConfigStreamPayload, CompressionIsDecidedFromTheZlibHeader) {
    EXPECT_TRUE(payload::isCompressed(std::vector<std::uint8_t>{0, 0, 0, 0xAA, 0x78, 0x9C}));
    EXPECT_TRUE(payload::isCompressed(std::vector<std::uint8_t>{0, 0, 0, 1, 0x78, 0xDA}));
    EXPECT_FALSE(
        payload::isCompressed(std::vector<std::uint8_t>{0, 0, 0, 1, 0x78, 0x9D})); // check bits wrong
    EXPECT_FALSE(payload::isCompressed(std::vector<std::uint8_t>{0x1F, 0x8B, 8, 0, 0, 0})); // gzip
    EXPECT_FALSE(payload::isCompressed(bytesOf("[lokomotive]\n")));
    EXPECT_FALSE(payload::isCompressed(std::vector<std::uint8_t>{0, 0, 0, 1, 0x78}));
}

TEST(ConfigStreamPayload, RawDeflateIsNotAccepted) {
    // A deflate stream without the zlib wrapper (windowBits -15) behind the size prefix.
    const std::string contents = "gleis\n";
    std::vector<std::uint8_t> deflated(64);
    z_stream zs{};
    deflateInit2(&zs, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY);
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(contents.data()));
    zs.avail_in = uInt(contents.size());
    zs.next_out = deflated.data();
    zs.avail_out = uInt(deflated.size());
    deflate(&zs, Z_FINISH);
    deflated.resize(zs.total_out);
    deflateEnd(&zs);
    EXPECT_FALSE(payload::isCompressed(withPrefix(6, deflated)));
}

TEST(ConfigStreamPayload, DamagedZlibStreamIsAnInflateError) {
    auto bytes = payload::compress(std::string(500, 'x') + "abc");
    bytes[8] ^= 0xFF;
    bytes[9] ^= 0xFF;
    const auto result = payload::inflate(bytes, 1 << 20);
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, StreamErrorKind::InflateFailed);
    EXPECT_NE(result.error().message.find("the zlib stream is damaged: "), std::string::npos)
        << result.error().message;
}

TEST(ConfigStreamPayload, TruncatedZlibStreamIsAnInflateError) {
    std::string contents;
    for (int i = 0; i < 200; ++i)
        contents += "lok\n .name=" + std::to_string(i * 7919) + "\n";
    auto bytes = payload::compress(contents);
    bytes.resize(bytes.size() / 2);
    const auto result = payload::inflate(bytes, 1 << 20);
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, StreamErrorKind::InflateFailed);
    EXPECT_NE(result.error().message.find("the zlib stream ends early after "), std::string::npos)
        << result.error().message;
}

TEST(ConfigStreamPayload, FileShorterThanItsPrefixIsASizeMismatch) {
    const auto result = payload::inflate(lyingPayload("short file\n", 40), 1 << 20);
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, StreamErrorKind::SizeMismatch);
    EXPECT_EQ(result.error().message, "the file inflates to 11 bytes, its size prefix announces 40");
}

TEST(ConfigStreamPayload, FileLongerThanItsPrefixStopsAtThePrefix) {
    const auto result = payload::inflate(lyingPayload(std::string(1000, 'a'), 10), 1 << 20);
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, StreamErrorKind::SizeMismatch);
    EXPECT_EQ(result.error().message,
              "the file inflates to more than the 10 bytes its size prefix announces");
}

TEST(ConfigStreamPayload, ZipBombWithAModestPrefixStopsEarly) {
    // 64 MiB of zeros compress to about 64 KiB; the prefix claims 100 bytes.
    const auto result = payload::inflate(lyingPayload(std::string(64u << 20, '\0'), 100), 16u << 20);
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, StreamErrorKind::SizeMismatch);
}

TEST(ConfigStreamPayload, PrefixAboveTheLimitIsRefusedBeforeInflating) {
    const auto result = payload::inflate(lyingPayload("x", 0xFFFFFFFF), 16u << 20);
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, StreamErrorKind::TooLarge);
    EXPECT_EQ(result.error().message, "the file announces 4294967295 bytes, above the limit of 16777216");
}

TEST(ConfigStreamPayload, ConfigurableLimit) {
    const auto bytes = payload::compress(std::string(2000, 'k'));
    EXPECT_EQ(payload::inflate(bytes, 1999).error().kind, StreamErrorKind::TooLarge);
    EXPECT_EQ(payload::inflate(bytes, 2000).value().size(), 2000u);
}

TEST(ConfigStreamPayload, TrailingPaddingAfterTheZlibStreamIsIgnored) {
    auto bytes = payload::compress("[gleisbildseite]\n");
    bytes.insert(bytes.end(), 7, 0);
    EXPECT_EQ(payload::inflate(bytes, 1 << 20).value(), "[gleisbildseite]\n");
}

TEST(ConfigStreamPayload, EmptyFileCompressesAndInflates) {
    const auto bytes = payload::compress("");
    EXPECT_EQ(payload::announcedSize(bytes), 0u);
    EXPECT_EQ(payload::inflate(bytes, 1 << 20).value(), "");
}

// ---- MS2 text form (document 8.4-8.8, field notes) --------------------------------------------

TEST(ConfigStreamPayload, EveryLineStartsAnEightByteFrame) {
    const std::string text = "[lokomotive]\nlok\n .uid=0xc00a\n .av=60\n .bv=40\n";
    const std::string padded = payload::padLines(text);
    EXPECT_EQ(padded, "[lokomotive]\n   "
                      "lok\n    "
                      " .uid=0xc00a\n   "
                      " .av=60\n"
                      " .bv=40\n");
    EXPECT_TRUE(payload::hasPaddedLines(padded));
    EXPECT_EQ(payload::stripLinePadding(padded), text);
}

TEST(ConfigStreamPayload, IndentationAtAFrameBoundarySurvives) {
    const std::string text = "[lokomotive]\n  .name=M4\n";
    EXPECT_EQ(payload::stripLinePadding(payload::padLines(text)), text);
}

TEST(ConfigStreamPayload, UnpaddedTextIsRecognised) {
    // The loknamen example of 8.5 as a station without padding would send it.
    const std::string text = "[lokomotive]\nlok\n  .nr=3\n  .name=MaK 1206 ACTS\nnumloks\n  .wert=8\n";
    EXPECT_FALSE(payload::hasPaddedLines(text));
    EXPECT_EQ(payload::plainText(bytesOf(text)), text);
}

TEST(ConfigStreamPayload, PlainTextLosesZeroPaddingAndLinePadding) {
    std::string stream = payload::padLines(".version=9\n.monat=2\n.jahr=10\n.anzahl=1078\n");
    stream.append(8 - stream.size() % 8, '\0');
    EXPECT_EQ(payload::plainText(bytesOf(stream)), ".version=9\n.monat=2\n.jahr=10\n.anzahl=1078\n");
}

TEST(ConfigStreamPayload, BinaryBytesKeepTheirZeros) {
    const std::vector<std::uint8_t> bytes{0x01, 0x00, 0x02, 0x0A, 0x20, 0x00, 0x00};
    const std::string text = payload::plainText(bytes);
    EXPECT_EQ(std::vector<std::uint8_t>(text.begin(), text.end()), bytes);
}

TEST(ConfigStreamPayload, ZerosInsideAnUnalignedLengthAreData) {
    const std::vector<std::uint8_t> bytes{'a', 'b', 'c', 0};
    EXPECT_EQ(payload::plainText(bytes), std::string("abc\0", 4));
}

// Found by fuzzing (issue 11): fewer bytes than the size prefix made inflate read before and past them.
TEST(ConfigStreamPayload, InflateOfFewerBytesThanTheSizePrefixIsAnError) {
    const std::vector<std::uint8_t> bytes{0xFB};
    const auto inflated = payload::inflate(bytes, 1024);
    ASSERT_FALSE(inflated.hasValue());
    EXPECT_EQ(inflated.error().kind, StreamErrorKind::InflateFailed);
    EXPECT_FALSE(payload::inflate(std::span<const std::uint8_t>(), 1024).hasValue());
}
