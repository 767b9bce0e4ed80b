#pragma once

// Helpers of the magnetartikel.cs2 tests (AccessoryFile*Test.cpp, MaginfoTest.cpp, AccessoryTypeTest.cpp):
// the document's examples, reading a file with its diagnostics, and comparing accessories.

#include "ConfigTestSupport.h"
#include "cs2config/AccessoryFile.h"

#include <gtest/gtest.h>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config::test::accessoryfile {

// 8.2: the document's magnetartikel.cs2 example.
inline constexpr std::string_view documentMagnetartikel = "[magnetartikel]\n"
                                                          "version\n"
                                                          ".major=0\n"
                                                          ".minor=1\n"
                                                          "artikel\n"
                                                          ".id=1\n"
                                                          ".name=src\n"
                                                          ".typ=lichtsignal_HP012_SH01\n"
                                                          ".stellung=2\n"
                                                          ".schaltzeit=200\n"
                                                          ".ungerade=0\n"
                                                          ".dectyp=mm2\n";

// 8.6: the document's maginfo stream.
inline constexpr std::string_view documentMaginfo = "[magnetartikel]\n"
                                                    "artikel\n"
                                                    "  .id=3\n"
                                                    "  .name=1.3\n"
                                                    "  .typ=rechtsweiche\n"
                                                    "  .schaltzeit=200\n"
                                                    "  .dectyp=mm2\n"
                                                    "artikel\n"
                                                    "  .id=4\n"
                                                    "  .name=1.4\n"
                                                    "  .typ=entkupplungsgleis\n"
                                                    "  .schaltzeit=200\n"
                                                    "  .dectyp=mm2\n";

using Read = ReadModel<AccessoryFile>;

inline Read readText(std::string_view text) {
    return readAs<AccessoryFile>(text, "magnetartikel.cs2");
}

inline Read readCorpusFile(std::string_view path) {
    return readText(readCorpus(path));
}

inline std::map<std::string, int> countBy(const AccessoryFile& file, std::string Accessory::*field) {
    std::map<std::string, int> counts;
    for (const Accessory& accessory : file.accessories)
        ++counts[accessory.*field];
    return counts;
}

inline void expectSameAccessories(const std::vector<Accessory>& actual,
                                  const std::vector<Accessory>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        SCOPED_TRACE("accessory " + std::to_string(i));
        EXPECT_EQ(actual[i].id, expected[i].id);
        EXPECT_EQ(actual[i].name, expected[i].name);
        EXPECT_EQ(actual[i].type, expected[i].type);
        EXPECT_EQ(actual[i].position, expected[i].position);
        EXPECT_EQ(actual[i].switchTimeMs, expected[i].switchTimeMs);
        EXPECT_EQ(actual[i].secondOutput, expected[i].secondOutput);
        EXPECT_EQ(actual[i].decoder, expected[i].decoder);
        EXPECT_EQ(actual[i].protocol, expected[i].protocol);
    }
}

inline const Accessory& byId(const AccessoryFile& file, std::int64_t id) {
    for (const Accessory& accessory : file.accessories)
        if (accessory.id == id)
            return accessory;
    throw std::out_of_range("no accessory " + std::to_string(id));
}

inline bool mentions(const Diagnostics& diagnostics, std::string_view text) {
    return diagnostics.formatAll().find(text) != std::string::npos;
}

} // namespace stellwerk::cs2config::test::accessoryfile
