#pragma once

// Helpers of the document example tests (DocumentChapter*Test.cpp, FieldNotesTest.cpp): frames in the
// document's notation, what describe() shows of them, and frames the decoder must refuse.

#include "TestSupport.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Fields.h"
#include "cs2/Messages.h"

#include <cstdint>
#include <gtest/gtest.h>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2::test {

// The decoded message of a frame in document notation; fails the test when it does not decode.
inline Message decodeText(std::string_view text) {
    const auto result = decode(frame(text));
    EXPECT_TRUE(result.hasValue()) << text << ": " << (result ? "" : result.error().message());
    return result ? *result : Message{};
}

// What describe() shows for one field of a frame: names and text as they are, numbers in decimal,
// flags as true/false; "<none>" when the message has no such field.
inline std::string described(std::string_view text, std::string_view key) {
    for (const auto& field : describe(decodeText(text))) {
        if (field.key != key)
            continue;
        switch (field.format) {
        case FieldFormat::Text:
            return field.text;
        case FieldFormat::Bool:
            return field.number ? "true" : "false";
        case FieldFormat::Decimal:
        case FieldFormat::Hex:
            break;
        }
        return std::to_string(field.number);
    }
    return "<none>";
}

// The frame must be refused by the decoder with an error of the given kind.
inline void expectRefused(std::string_view text, DecodeErrorKind kind) {
    const auto result = decode(frame(text));
    ASSERT_FALSE(result.hasValue()) << text << " decoded as " << messageName(result->body);
    EXPECT_EQ(result.error().kind, kind) << text << ": " << result.error().message();
}

inline bool contains(std::string_view text, std::string_view part) {
    return text.find(part) != std::string_view::npos;
}

// A document-notation frame with the given id and bytes ("00404711 8 6C 6F ...").
inline std::string frameText(std::string_view id, const std::vector<std::uint8_t>& bytes) {
    static constexpr char Digits[] = "0123456789ABCDEF";
    std::string text = std::string(id) + " " + std::to_string(bytes.size());
    for (auto byte : bytes) {
        text += ' ';
        text += Digits[byte >> 4];
        text += Digits[byte & 0x0F];
    }
    return text;
}

// A config data request (7.1) for a file key, zero padded to eight bytes.
inline std::string configRequest(std::string_view id, std::string_view key) {
    std::vector<std::uint8_t> bytes(8, 0);
    for (std::size_t i = 0; i < key.size() && i < 8; ++i)
        bytes[i] = std::uint8_t(key[i]);
    return frameText(id, bytes);
}
} // namespace stellwerk::cs2::test
