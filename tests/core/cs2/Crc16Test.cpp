#include "cs2/Crc16.h"

#include "TestSupport.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <vector>

using namespace stellwerk::cs2;

TEST(Crc16, CcittFalseCheckValue) {
    const std::string text = "123456789";
    EXPECT_EQ(crc16({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}), 0x29B1);
}

TEST(Crc16, EmptyInputIsTheStartValue) {
    EXPECT_EQ(crc16({}), 0xFFFF);
}

TEST(Crc16, MatchesTheDocumentsBitwiseAlgorithm) {
    // The routine printed in chapter 7.2, applied byte by byte.
    auto update = [](std::uint16_t acc, std::uint8_t input) {
        acc = std::uint16_t(acc ^ (input << 8));
        for (int i = 0; i < 8; ++i)
            acc = (acc & 0x8000) ? std::uint16_t((acc << 1) ^ 0x1021) : std::uint16_t(acc << 1);
        return acc;
    };
    std::vector<std::uint8_t> bytes;
    for (int i = 0; i < 300; ++i)
        bytes.push_back(std::uint8_t(i * 37 + 11));
    std::uint16_t expected = 0xFFFF;
    for (auto b : bytes)
        expected = update(expected, b);
    EXPECT_EQ(crc16(bytes), expected);
}

// The logged stream of the corpus: header len=0x5F crc=0x2170, then 12 data frames.
TEST(Crc16, CorpusStreamChecksumCoversThePaddedDataBytes) {
    std::ifstream in(test::corpusFile("GBert__railroad/can2udp/src/example_zlib.txt"));
    ASSERT_TRUE(in) << "example_zlib.txt must be readable";
    std::vector<std::uint8_t> data;
    std::optional<ConfigDataStream> header;
    std::string line;
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
        const auto parsed = stellwerk::can::parseFrame(line);
        ASSERT_TRUE(parsed.hasValue()) << line;
        const auto message = decode(parsed->frame);
        ASSERT_TRUE(message.hasValue()) << line;
        const auto& stream = std::get<ConfigDataStream>(message->body);
        if (stream.form == ConfigDataStream::Form::Data)
            data.insert(data.end(), stream.data.begin(), stream.data.end());
        else
            header = stream;
    }
    ASSERT_TRUE(header.has_value());
    EXPECT_EQ(header->form, ConfigDataStream::Form::BroadcastHeader);
    EXPECT_EQ(header->length, 0x5Fu);
    EXPECT_EQ(header->crc, 0x2170);
    ASSERT_EQ(data.size(), 96u);
    EXPECT_EQ(crc16(data), 0x2170);
    EXPECT_EQ(crc16(std::span(data).first(95)), 0x772F) << "field notes: 0x772F over the 95 unpadded bytes";
}
