#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
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

// A typed model read from text, and what parsing and reading reported.
template <class Model>
struct ReadModel {
    Diagnostics diagnostics;
    Model file;
};

// Parses `text` and reads it as a Model (AccessoryFile, RouteFile, LocomotiveFile, ...).
template <class Model>
ReadModel<Model> readAs(std::string_view text, std::string fileName) {
    Parsed parsed = parseText(text, std::move(fileName));
    Model file = Model::read(parsed.document, parsed.diagnostics);
    return {std::move(parsed.diagnostics), std::move(file)};
}

// The file with line `lineNumber` (1-based) replaced by `text`.
inline std::string withLine(std::string_view bytes, int lineNumber, std::string_view text) {
    std::size_t start = 0;
    for (int line = 1; line < lineNumber && start != std::string_view::npos; ++line)
        start = bytes.find('\n', start) + 1;
    const std::size_t end = std::min(bytes.find('\n', start), bytes.size());
    return std::string(bytes.substr(0, start)) + std::string(text) + std::string(bytes.substr(end));
}

// True when every record with this keyword stands in one unbroken run (what replaceRecords keeps).
inline bool recordsGrouped(const Document& document, std::string_view keyword) {
    bool seen = false;
    bool ended = false;
    for (const Node& node : document.topLevel()) {
        if (!node.isEntry())
            continue;
        const bool match = node.level() == 0 && node.key() == keyword;
        if (match && ended)
            return false;
        seen = seen || match;
        ended = ended || (seen && !match);
    }
    return true;
}

// Random damage to a file (bytes changed, inserted or cut out), biased towards the characters that carry
// the format's structure.
inline std::string damaged(std::string bytes, std::mt19937& random) {
    static constexpr std::string_view structural = ".=\n \r0123456789-x[]az";
    const auto pick = [&random](int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(random);
    };
    const auto character = [&] {
        return pick(0, 3) == 0 ? static_cast<char>(pick(0, 255))
                               : structural[static_cast<std::size_t>(pick(0, structural.size() - 1))];
    };
    for (int edits = pick(1, 8); edits > 0; --edits) {
        const auto at = static_cast<std::size_t>(pick(0, static_cast<int>(bytes.size())));
        const int kind = pick(0, 2);
        if (kind == 0 && at < bytes.size())
            bytes[at] = character();
        else if (kind == 1)
            bytes.insert(at, 1, character());
        else if (at < bytes.size())
            bytes.erase(at, static_cast<std::size_t>(pick(1, 40)));
    }
    return bytes;
}

} // namespace stellwerk::cs2config::test
