#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/TrackPage.h"
#include "cs2config/TrackPlan.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// The file of a page, as a CS2 stores it beside its index: <directory>/gleisbilder/<page name>.cs2.
// nullopt for names that cannot be a file name there (empty, ".", "..", a path separator or a control
// character), so that nothing read from a file can point outside the layout directory.
std::optional<std::filesystem::path> trackPageFile(const std::filesystem::path& directory,
                                                   std::string_view pageName);
// The config-stream key that carries a page over CAN: "gbs-<page id>".
std::string trackPageStreamKey(std::int64_t pageId);

// One page of a loaded layout: its index entry, where its file is, and what reading it found.
struct TrackLayoutPage {
    std::int64_t id = 0;
    std::string name;
    std::filesystem::path file; // empty when the name cannot be a file name
    bool loaded = false;        // false when the file is missing or unreadable
    bool missing = false;       // the page file does not exist
    TrackPage page;
    Diagnostics diagnostics;
};

// A whole layout directory: gleisbild.cs2 and the page file of every page it lists.
struct TrackLayout {
    static constexpr std::size_t maxFileSize = 16 * 1024 * 1024;

    std::filesystem::path directory;
    TrackPlan plan;
    Diagnostics diagnostics; // the index's, including page files that could not be loaded
    std::vector<TrackLayoutPage> pages;

    // Reads the index file and the page files beside it. Never throws; every problem is reported in
    // `diagnostics` or in the page's own.
    static TrackLayout load(const std::filesystem::path& indexFile);
    // The pages of `directory` whose gleisbild.cs2 is missing: every file of pageFiles(directory) under an
    // index made up for them (numbered from 0 in that order, named after the files). `diagnostics` says
    // that the index is missing and what was done instead.
    static TrackLayout loadPages(const std::filesystem::path& directory);
    // One page file alone ("config/gleisbilder/Bahnhof.cs2"), as page 0 of an index made up for it; the
    // layout's directory is the one above `gleisbilder`, or the file's own folder.
    static TrackLayout loadPageFile(const std::filesystem::path& pageFile);
    // The `.cs2` files in `directory`/gleisbilder in the order of their names, numbers in them counted
    // as numbers ("2 - Bottom" before "10 - Hafen"); empty when there are none.
    static std::vector<std::filesystem::path> pageFiles(const std::filesystem::path& directory);
};

std::string toJson(const TrackLayout& layout);

} // namespace stellwerk::cs2config
