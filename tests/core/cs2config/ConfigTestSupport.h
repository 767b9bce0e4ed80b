#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <string_view>

namespace stellwerk::cs2config::test {

// The corpus files, read in place from ../shared/corpus (never copied into the project).
namespace corpus {
inline constexpr std::string_view gleisbildGbert =
    "GBert__railroad/can2udp/files/maerklin/config/gleisbild.cs2";
inline constexpr std::string_view karben =
    "GBert__railroad/can2udp/files/maerklin/config/gleisbilder/karben.cs2";
inline constexpr std::string_view gbs0 = "GBert__railroad/can2udp/src/gbs-0.cs2";
inline constexpr std::string_view gleisbildMrFlexi = "MrFlexi__TrainControll/gleisbild.cs2";
inline constexpr std::string_view gleisbildSample =
    "bob123456678__TrainControl/cs2_sample_layout/config/gleisbild.cs2";
inline constexpr std::string_view testPage =
    "bob123456678__TrainControl/cs2_sample_layout/config/gleisbilder/5 - Test.cs2";
inline constexpr std::string_view lokomotiveTrainControl = "bob123456678__TrainControl/test/lokomotive.cs2";
inline constexpr std::string_view lokomotiveGbert =
    "GBert__railroad/can2udp/files/maerklin/config/lokomotive.cs2";
inline constexpr std::string_view lokomotiveSrseii = "RalfMende__srseii-portal/package/var/lokomotive.cs2";
inline constexpr std::string_view lokomotiveCorrupted = "joao404__z21MaerklinCan/data/config/lokomotive.cs2";
inline constexpr std::string_view magnetartikelTrainControl =
    "bob123456678__TrainControl/test/magnetartikel.cs2";
inline constexpr std::string_view magnetartikelGbert =
    "GBert__railroad/can2udp/files/maerklin/config/magnetartikel.cs2";
inline constexpr std::string_view fahrstrassen = "bob123456678__TrainControl/test/fahrstrassen.cs2";
inline constexpr std::string_view cs3TrackPlan =
    "RalfMende__LocDbConverterConsole/ExampleFiles/cs3/work/config/gbs/plneu/2.cs2";
inline constexpr std::string_view cs3Loco =
    "RalfMende__LocDbConverterConsole/ExampleFiles/cs3/work/config/lok/loks/260#20417-1#20DB.cs2";
inline constexpr std::string_view exampleZlib = "GBert__railroad/can2udp/src/example_zlib.txt";
} // namespace corpus

inline std::filesystem::path corpusPath(std::string_view relative) {
    return std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus" / relative;
}

// The bytes of a corpus file; the test fails (not skips) when the file is missing.
inline std::string readCorpus(std::string_view relative) {
    const std::filesystem::path path = corpusPath(relative);
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in.good()) << "corpus file missing: " << path;
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// Parses text and keeps the diagnostics for the test to inspect.
struct Parsed {
    Diagnostics diagnostics;
    Document document;
};

inline Parsed parseText(std::string_view text, std::string fileName = "test.cs2") {
    Diagnostics diagnostics(std::move(fileName));
    Document document = Document::parse(text, diagnostics);
    return {std::move(diagnostics), std::move(document)};
}

inline Parsed parseCorpus(std::string_view relative) {
    return parseText(readCorpus(relative), std::filesystem::path(relative).filename().string());
}

} // namespace stellwerk::cs2config::test
