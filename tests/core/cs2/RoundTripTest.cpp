// Properties over the whole input space: whatever decodes encodes back to the same bytes, whatever
// does not decode is a typed error, and what the description shows is enough to build the frame.

#include "TestSupport.h"
#include "cs2/Fields.h"

#include <gtest/gtest.h>
#include <random>

using namespace stellwerk::cs2;

namespace {

std::string fieldText(const stellwerk::cs2::Field& field) {
    switch (field.format) {
    case stellwerk::cs2::FieldFormat::Hex: {
        char buffer[24];
        std::snprintf(buffer, sizeof buffer, "0x%llX", static_cast<unsigned long long>(field.number));
        return buffer;
    }
    case stellwerk::cs2::FieldFormat::Bool:
        return field.number ? "true" : "false";
    case stellwerk::cs2::FieldFormat::Text:
        return field.text;
    case stellwerk::cs2::FieldFormat::Decimal:
        break;
    }
    return std::to_string(field.number);
}

// Payload patterns for one DLC: edges plus pseudo-random bytes from a fixed seed.
std::vector<std::array<std::uint8_t, 8>> payloads(std::mt19937& random, int count) {
    std::vector<std::array<std::uint8_t, 8>> out;
    out.push_back({});
    out.push_back({0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF});
    out.push_back({0x00, 0x00, 0xC0, 0x03, 0x01, 0x01, 0x00, 0x0A});
    out.push_back({0x43, 0x53, 0x32, 0x08, 0x0B, 0x01, 0x00, 0x03});
    for (int i = 0; i < count; ++i) {
        std::array<std::uint8_t, 8> bytes{};
        for (auto& b : bytes)
            b = std::uint8_t(random());
        // Bias towards small values so that more frames pass range checks and reach every form.
        if (i % 2 == 0)
            bytes[4] = std::uint8_t(bytes[4] % 0x0D), bytes[5] &= 0x07, bytes[6] &= 0x01;
        out.push_back(bytes);
    }
    return out;
}

// Every well-formed frame over all commands, both directions and all DLCs.
template <class Check>
void forEveryFrame(Check check) {
    std::mt19937 random(20121207);
    for (unsigned command = 0; command < 256; ++command)
        for (bool response : {false, true})
            for (std::uint8_t dlc = 0; dlc <= 8; ++dlc)
                for (const auto& bytes : payloads(random, 24)) {
                    const auto prio = std::uint8_t(random() & 0x0F);
                    const auto hash = std::uint16_t(random());
                    check(CanFrame{stellwerk::cs2::makeId(prio, std::uint8_t(command), response, hash), dlc,
                                   bytes});
                }
}

} // namespace

TEST(RoundTrip, EveryDecodedFrameEncodesToTheSameBytes) {
    std::size_t decoded = 0, refused = 0;
    forEveryFrame([&](const CanFrame& input) {
        const auto result = decode(input);
        if (!result) {
            ++refused;
            const auto kind = result.error().kind;
            ASSERT_TRUE(kind == DecodeErrorKind::TooShort || kind == DecodeErrorKind::UnexpectedLength ||
                        kind == DecodeErrorKind::ReservedValue)
                << formatDocument(input);
            ASSERT_FALSE(result.error().detail.empty());
            return;
        }
        ++decoded;
        ASSERT_EQ(formatDocument(encode(*result)), formatDocument(input)) << messageName(result->body);
    });
    EXPECT_GT(decoded, 50000u);
    EXPECT_GT(refused, 1000u);
}

TEST(RoundTrip, DescriptionIsEnoughToBuildTheSameFrame) {
    std::size_t checked = 0;
    forEveryFrame([&](const CanFrame& input) {
        const auto result = decode(input);
        if (!result)
            return;
        std::vector<KeyValue> arguments{{"prio", std::to_string(stellwerk::cs2::prio(input))},
                                        {"response", stellwerk::cs2::isResponse(input) ? "true" : "false"},
                                        {"hash", std::to_string(stellwerk::cs2::hash(input))}};
        for (const auto& field : describe(*result))
            if (!field.derived)
                arguments.emplace_back(std::string(field.key), fieldText(field));
        const auto rebuilt = buildMessage(messageName(result->body), arguments);
        ASSERT_TRUE(rebuilt.hasValue()) << formatDocument(input) << ": " << rebuilt.error();
        ASSERT_EQ(formatDocument(encode(*rebuilt)), formatDocument(input)) << messageName(result->body);
        ++checked;
    });
    EXPECT_GT(checked, 50000u);
}

TEST(RoundTrip, EveryIdentifierSurvives) {
    // All of prio x command x response, with hashes at the edges and in between.
    for (std::uint32_t prio = 0; prio < 16; ++prio)
        for (std::uint32_t command = 0; command < 256; ++command)
            for (bool response : {false, true})
                for (std::uint16_t hash : {0x0000, 0x0300, 0x4711, 0x7FFF, 0x8000, 0xFFFF}) {
                    const CanFrame input{
                        stellwerk::cs2::makeId(std::uint8_t(prio), std::uint8_t(command), response, hash),
                        8,
                        {0, 0, 0, 0, 0, 0, 0, 0}};
                    const auto bytes = input.toNetwork();
                    ASSERT_EQ(CanFrame::fromNetwork(bytes), input);
                    const auto result = decode(input);
                    if (result) {
                        ASSERT_EQ(encode(*result).id, input.id);
                    }
                }
}

TEST(RoundTrip, EveryCommandHasADecoderOrIsUnknown) {
    for (unsigned command = 0; command < 256; ++command) {
        const auto result =
            decode(CanFrame{stellwerk::cs2::makeId(0, std::uint8_t(command), false, 0x4711), 8, {}});
        if (result && std::holds_alternative<Unknown>(result->body)) {
            EXPECT_EQ(std::get<Unknown>(result->body).command, command);
        }
    }
}
