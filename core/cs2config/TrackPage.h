#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/TrackElement.h"
#include "cs2config/TrackFile.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// The grid a page's elements cover. A CS2 draws from column 0, row 0, so the page needs
// columns() x rows() tiles.
struct TrackArea {
    int left = 0;
    int top = 0;
    int right = 0;
    int bottom = 0;

    int columns() const { return right + 1; }
    int rows() const { return bottom + 1; }
};

// One page of the track plan: `gleisbilder/<page name>.cs2`, or `gbs-<page id>` from the CAN stream
// (same format), section `[gleisbildseite]`.
struct TrackPage {
    static constexpr std::string_view section = "gleisbildseite";

    Document document = Document::create(section);
    TrackPlanFormat format = TrackPlanFormat::Cs2Grid;
    std::optional<TrackFileVersion> version = TrackFileVersion{1, 0}; // real files write `.major=1`
    std::vector<TrackElement> elements;

    static TrackPage read(const Document& document, Diagnostics& diagnostics);
    // The source document with the changed lines rewritten; unchanged when nothing changed (and
    // always unchanged for a CS3 `[conf]` plan, which is not read).
    Document write() const;

    // nullopt for a page without elements.
    std::optional<TrackArea> area() const;
};

std::string toJson(const TrackPage& page);
// The page as a JSON object (an array element when `key` is empty), for composing larger documents.
void writeJson(JsonWriter& json, const TrackPage& page, std::string_view key = {});

} // namespace stellwerk::cs2config
