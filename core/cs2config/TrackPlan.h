#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Node.h"
#include "cs2config/TrackElement.h"
#include "cs2config/TrackFile.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// The `groesse` record: tiles per page. The document fixes it at 20 x 15; real files leave it empty.
struct TrackGridSize {
    std::optional<std::int64_t> width;
    std::optional<std::int64_t> height;

    friend bool operator==(const TrackGridSize&, const TrackGridSize&) = default;
};

// One `seite` record of the index: a page's number and name (its file is gleisbilder/<name>.cs2).
struct TrackPageEntry {
    static constexpr std::string_view keyword = "seite";

    std::int64_t id = 0; // a missing `.id` means 0 (real files leave it out on the first page)
    std::string name;
    Node source; // the record as read; empty for a new page

    int line() const { return source.lineNumber(); }
};

// The track plan index `gleisbild.cs2` (document 8.3): the pages, their grid size and the page
// last shown. The document's example also puts `element` records here; they are read like a page's.
struct TrackPlan {
    static constexpr std::string_view section = "gleisbild";

    Document document = Document::create(section);
    TrackPlanFormat format = TrackPlanFormat::Cs2Grid;
    std::optional<TrackFileVersion> version = TrackFileVersion{1, 0}; // real files write `.major=1`
    std::optional<TrackGridSize> size = TrackGridSize{};              // real files write an empty one
    // `zuletztBenutzt`: the name of the page last shown (`.name`; the document says `.seite`).
    std::optional<std::string> lastUsedPage;
    std::vector<TrackPageEntry> pages;
    std::vector<TrackElement> elements;

    static TrackPlan read(const Document& document, Diagnostics& diagnostics);
    // The source document with the changed lines rewritten; unchanged when nothing changed.
    Document write() const;

    // The first page with this id or name; null when there is none.
    const TrackPageEntry* pageWithId(std::int64_t id) const;
    const TrackPageEntry* pageNamed(std::string_view name) const;
    // The page lastUsedPage names (by name, or by number as the document's `.seite=0` does).
    const TrackPageEntry* lastUsed() const;
};

std::string toJson(const TrackPlan& plan);
// The index as a JSON object (an array element when `key` is empty), for composing larger documents.
void writeJson(JsonWriter& json, const TrackPlan& plan, std::string_view key = {});

} // namespace stellwerk::cs2config
