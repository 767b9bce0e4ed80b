#pragma once

// Helpers shared by the codec tests: frames from the document's notation, and corpus paths.

#include "can/FrameText.h"
#include "cs2/Codec.h"

#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <string_view>

namespace stellwerk::cs2::test {

// A frame written as in the document ("00004711 5 00 00 00 00 00"); fails the test if unreadable.
inline CanFrame frame(std::string_view text) {
    const auto parsed = can::parseFrame(text);
    EXPECT_TRUE(parsed.hasValue()) << text << ": " << (parsed ? "" : parsed.error());
    return parsed ? parsed->frame : CanFrame{};
}

// Decodes and expects success, returning the body as T (fails the test otherwise).
template <class T>
T decodeAs(std::string_view text, Message* envelope = nullptr) {
    const auto result = decode(frame(text));
    EXPECT_TRUE(result.hasValue()) << text << ": " << (result ? "" : result.error().message());
    if (!result)
        return T{};
    if (envelope)
        *envelope = *result;
    const T* body = std::get_if<T>(&result->body);
    EXPECT_NE(body, nullptr) << text << " decoded as " << messageName(result->body);
    return body ? *body : T{};
}

// Encoding the decoded message gives back exactly the input bytes.
inline void expectRoundTrip(std::string_view text) {
    const CanFrame input = frame(text);
    const auto result = decode(input);
    ASSERT_TRUE(result.hasValue()) << text;
    EXPECT_EQ(formatDocument(encode(*result)), formatDocument(input));
}

// A file of the shared corpus; the test fails loudly (never skips) when it is missing.
inline std::filesystem::path corpusFile(std::string_view relative) {
    const std::filesystem::path path = std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus" / relative;
    EXPECT_TRUE(std::filesystem::exists(path)) << "corpus file missing: " << path;
    return path;
}

} // namespace stellwerk::cs2::test
