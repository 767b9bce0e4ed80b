// Which file a locomotive's `.icon` names, and which bytes are shown as its picture.

#include "cs2config/LocomotivePicture.h"

#include "ConfigTestSupport.h"
#include "LocomotiveFileTestSupport.h"

#include <gtest/gtest.h>
#include <string>

namespace stellwerk::cs2config::test {
namespace {

namespace pic = cs2config::picture;

const std::string Iend("\0\0\0\0IEND\xAE\x42\x60\x82", 12);

// A PNG header (signature and IHDR) of the given size, followed by `extra` bytes.
std::string pngHeader(std::uint32_t width, std::uint32_t height, std::size_t extra = 0) {
    std::string bytes("\x89PNG\r\n\x1a\n", 8);
    auto append32 = [&bytes](std::uint32_t v) {
        for (int shift = 24; shift >= 0; shift -= 8)
            bytes.push_back(static_cast<char>((v >> shift) & 0xFF));
    };
    append32(13);
    bytes += "IHDR";
    append32(width);
    append32(height);
    bytes += std::string("\x08\x06\x00\x00\x00", 5);
    bytes += std::string(4 + extra, '\0'); // CRC and whatever follows
    return bytes + Iend;
}

TEST(LocomotivePictureName, ACs2NameIsTheFileNameWithPng) {
    EXPECT_EQ(pic::fileName("BR 218"), "BR 218.png");
    EXPECT_EQ(pic::fileName("Köf III"), "Köf III.png");
    EXPECT_EQ(pic::fileName("V 60.PNG"), "V 60.PNG");
}

TEST(LocomotivePictureName, ACs3PathGivesItsLastSegment) {
    EXPECT_EQ(pic::fileName("/usr/local/cs3/lokicons/mSD3_Logo"), "mSD3_Logo.png");
    EXPECT_EQ(pic::fileName("#2Fusr#2Flocal#2Fcs3#2Flokicons#2FmSD3_Logo"), "mSD3_Logo.png");
    EXPECT_EQ(pic::fileName("#2fusr#2flokicons#2fBR 86"), "BR 86.png");
}

TEST(LocomotivePictureName, TheCs3FileInTheCorpusNamesItsPicture) {
    const locofile::ReadFile read = locofile::readCorpusLocomotives(corpus::cs3Loco);
    ASSERT_EQ(read.file.locomotives.size(), 1u);
    EXPECT_EQ(pic::fileName(read.file.locomotives.front().icon), "mSD3_Logo.png");
}

TEST(LocomotivePictureName, NamesThatCouldLeaveTheFolderOrTheUrlNameNone) {
    for (const std::string_view icon :
         {std::string_view(""), std::string_view("/"), std::string_view("lokicons/"), std::string_view(".."),
          std::string_view("a/.."), std::string_view("."), std::string_view("a\\b"), std::string_view("a\nb"),
          std::string_view("a\x7f"), std::string_view("x#41"), std::string_view("what?x=1"),
          std::string_view("\xe4\xfc"), std::string_view("#2F"), std::string_view(".png"),
          std::string_view("icons/.PNG")})
        EXPECT_FALSE(pic::fileName(icon)) << icon;
    EXPECT_FALSE(pic::fileName(std::string(pic::MaxNameBytes + 1, 'a')));
    EXPECT_TRUE(pic::fileName(std::string(pic::MaxNameBytes, 'a')));
}

TEST(LocomotivePictureBytes, ASoundHeaderGivesTheSize) {
    pic::Size size;
    EXPECT_EQ(pic::problem(pngHeader(240, 80, 100), &size), std::nullopt);
    EXPECT_EQ(size.width, 240);
    EXPECT_EQ(size.height, 80);
}

TEST(LocomotivePictureBytes, WhatIsNotAPictureSaysWhy) {
    EXPECT_EQ(pic::problem(""), "not a PNG picture (too short)");
    EXPECT_EQ(pic::problem("<html><body>404 Not Found</body></html>"), "not a PNG picture");
    std::string gif = pngHeader(1, 1);
    gif.replace(0, 4, "GIF8");
    EXPECT_EQ(pic::problem(gif), "not a PNG picture");
    std::string noHeader = pngHeader(10, 10);
    noHeader.replace(12, 4, "IDAT");
    EXPECT_EQ(pic::problem(noHeader), "a damaged PNG picture (no IHDR header)");
    EXPECT_EQ(pic::problem(pngHeader(0, 80)), "a damaged PNG picture (no pixels)");
    EXPECT_EQ(pic::problem(pngHeader(4000, 80)), "4000 x 80 pixels, larger than 1024 x 1024");
    EXPECT_EQ(pic::problem(pngHeader(240, 0xFFFFFFFF)), "240 x 4294967295 pixels, larger than 1024 x 1024");
    const std::string cut = pngHeader(240, 80, 500);
    EXPECT_EQ(pic::problem(cut.substr(0, cut.size() - 1)), "a cut-off PNG picture (no IEND at its end)");
    EXPECT_EQ(pic::problem(cut.substr(0, 300)), "a cut-off PNG picture (no IEND at its end)");
    EXPECT_EQ(pic::problem(pngHeader(240, 80, pic::MaxBytes)),
              std::to_string(pngHeader(240, 80, pic::MaxBytes).size()) +
                  " bytes, more than the 262144 a locomotive picture may have");
}

} // namespace
} // namespace stellwerk::cs2config::test
