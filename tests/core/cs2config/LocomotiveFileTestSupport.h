#pragma once

// Helpers of the lokomotive.cs2 tests (LocomotiveFileTest.cpp, LocomotiveCorpusQuirksTest.cpp): reading a
// file with its diagnostics, comparing models and texts line by line.

#include "ConfigTestSupport.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/LocomotiveFile.h"
#include "cs2config/LocomotiveJson.h"
#include "cs2config/LocomotiveValues.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stellwerk::cs2config::test::locofile {

struct ReadFile {
    std::string bytes;
    Diagnostics diagnostics;
    LocomotiveFile file;
};

inline ReadFile readLocomotives(std::string bytes, std::string name = "lokomotive.cs2") {
    ReadFile read{std::move(bytes), Diagnostics(std::move(name)), {}};
    const Document document = Document::parse(read.bytes, read.diagnostics);
    read.file = LocomotiveFile::read(document, read.diagnostics);
    return read;
}

inline ReadFile readCorpusLocomotives(std::string_view path) {
    return readLocomotives(readCorpus(path));
}

// Every diagnostic as "line: message; action", for failure messages.
inline std::string listed(const Diagnostics& diagnostics) {
    return diagnostics.formatAll();
}

// Expects exactly these diagnostics, in order: the line and a part of the message.
inline void expectDiagnostics(const Diagnostics& diagnostics,
                              const std::vector<std::pair<int, std::string>>& expected) {
    ASSERT_EQ(diagnostics.items().size(), expected.size()) << listed(diagnostics);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(diagnostics.items()[i].line, expected[i].first) << listed(diagnostics);
        EXPECT_NE(diagnostics.items()[i].message.find(expected[i].second), std::string::npos)
            << "expected '" << expected[i].second << "' in: " << diagnostics.items()[i].message;
    }
}

inline std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

// The lines that differ between two texts of the same length in lines.
inline std::vector<std::string> changedLines(const std::string& before, const std::string& after) {
    const std::vector<std::string> a = splitLines(before);
    const std::vector<std::string> b = splitLines(after);
    EXPECT_EQ(a.size(), b.size());
    std::vector<std::string> changed;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        if (a[i] != b[i])
            changed.push_back(std::to_string(i + 1) + ": " + b[i]);
    return changed;
}

// All typed fields of a locomotive (not where it came from), to compare a model with its re-read.
inline std::string typed(const Locomotive& locomotive) {
    JsonWriter json(false);
    writeLocomotiveJson(json, {}, locomotive);
    return std::regex_replace(json.text(), std::regex("\"line\":[0-9]+,"), "");
}

inline void expectSameLocomotives(const LocomotiveFile& expected, const LocomotiveFile& actual) {
    ASSERT_EQ(expected.locomotives.size(), actual.locomotives.size());
    for (std::size_t i = 0; i < expected.locomotives.size(); ++i)
        EXPECT_EQ(typed(expected.locomotives[i]), typed(actual.locomotives[i])) << "locomotive " << i;
}

// Writes the model and reads the result again.
inline ReadFile rewritten(const LocomotiveFile& file) {
    return readLocomotives(file.write().serialize());
}

inline std::size_t countDecoder(const LocomotiveFile& file, LocomotiveDecoder decoder) {
    return static_cast<std::size_t>(
        std::count_if(file.locomotives.begin(), file.locomotives.end(),
                      [decoder](const Locomotive& l) { return l.decoder == decoder; }));
}

std::size_t countFunctions(const LocomotiveFile& file, auto predicate) {
    std::size_t count = 0;
    for (const Locomotive& locomotive : file.locomotives)
        count += static_cast<std::size_t>(
            std::count_if(locomotive.functions.begin(), locomotive.functions.end(), predicate));
    return count;
}

inline Locomotive& named(LocomotiveFile& file, std::string_view name) {
    const auto found = std::find_if(file.locomotives.begin(), file.locomotives.end(),
                                    [name](const Locomotive& l) { return l.name == name; });
    EXPECT_NE(found, file.locomotives.end()) << name;
    return *found;
}

} // namespace stellwerk::cs2config::test::locofile
