#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/Node.h"
#include "cs2config/TrackFile.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// One `element` record of the status file: which tile, and the position it shows.
struct TrackElementStatus {
    static constexpr std::string_view keyword = "element";

    // `.id`, written in decimal. mrsystem fills it from its own track plan entries; whether a CS2 means a
    // tile position (as in the pages) or a page there is not known, so it is kept as a plain number.
    std::int64_t id = 0;
    std::int64_t state = 0; // `.zustand`; left out when 0
    Node source;            // the record as read; empty for a new entry

    int line() const { return source.lineNumber(); }
};

// The track plan status file `gleisbild.sr2` (config stream key `gbsstat`, document 7.1: "current
// state of a track plan page"). The document gives no format. This model follows the only writer of
// it we found, mrsystem's gbsstat.c (Michael Bernstein's CS2 software): `[gleisbild]`, a `version`
// record with `.major=0` and `.minor=1`, then one `element` record per tile with `.id` and `.zustand`,
// numbers in decimal, `.zustand` left out when 0. Unknown records and keys are kept and reported.
struct TrackStatusFile {
    static constexpr std::string_view section = "gleisbild";

    Document document = Document::create(section);
    std::optional<TrackFileVersion> version = TrackFileVersion{0, 1};
    std::vector<TrackElementStatus> elements;

    static TrackStatusFile read(const Document& document, Diagnostics& diagnostics);
    // The source document with the changed lines rewritten; unchanged when nothing changed.
    Document write() const;

    // The first entry for this id; null when there is none.
    const TrackElementStatus* find(std::int64_t id) const;
};

std::string toJson(const TrackStatusFile& status);

} // namespace stellwerk::cs2config
