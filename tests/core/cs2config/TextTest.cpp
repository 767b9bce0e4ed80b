// Whether bytes are UTF-8 decides how a file is read and whether a report may be printed as it is.

#include "cs2config/Text.h"

#include <gtest/gtest.h>

namespace stellwerk::cs2config::test {
namespace {

using namespace std::string_view_literals;

TEST(Utf8, AsciiAndWellFormedSequencesAreUtf8) {
    EXPECT_TRUE(isValidUtf8(""));
    EXPECT_TRUE(isValidUtf8("Gleis 1 [magnetartikel] ~\x7F"));
    EXPECT_TRUE(isValidUtf8("Stra\xC3\x9F"
                            "enbahn \xE2\x82\xAC \xF0\x9F\x9A\x82 end"));
    EXPECT_TRUE(isValidUtf8("\xF4\x8F\xBF\xBF")); // U+10FFFF
}

TEST(Utf8, BrokenSequencesAnywhereAreNotUtf8) {
    for (const std::string_view bytes : {"Gleis \xE4"sv, "\xE4 Gleis"sv, "abc\x80"sv, "abc\xC0\xAF"sv,
                                         "abc\xE0\x80\xAF"sv, "abc\xED\xA0\x80"sv, "abc\xF4\x90\x80\x80"sv,
                                         "abc\xE2\x82"sv, "abc\xC3"sv, "\xC3(abc"sv, "\xFF"sv, "ok\0\xFE"sv})
        EXPECT_FALSE(isValidUtf8(bytes)) << latin1ToUtf8(bytes);
}

} // namespace
} // namespace stellwerk::cs2config::test
