#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/Node.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// What the track plan files (index, pages, status file) have in common as whole files.
namespace stellwerk::cs2config {

// The `version` record the track plan files start with.
struct TrackFileVersion {
    std::int64_t major = 0;
    std::int64_t minor = 0;

    friend bool operator==(const TrackFileVersion&, const TrackFileVersion&) = default;
};

// Which track plan a file holds: the CS2 grid these models read, or a CS3's own pixel format.
enum class TrackPlanFormat : std::uint8_t { Cs2Grid, Cs3Pixels };

// "cs2-grid" or "cs3-pixels".
std::string_view trackPlanFormatName(TrackPlanFormat format);

// Checks the `[section]` header. A CS3's own `[conf]` track plan is reported as an error and gives
// Cs3Pixels; any other unexpected header is reported and the file read anyway.
TrackPlanFormat checkTrackSection(const Document& document, std::string_view expected,
                                  std::string_view fileKind, Diagnostics& diagnostics);
// Reports records with a keyword not in `known` (once per keyword) and a second copy of a record that
// may appear only once (`single`).
void checkRecords(const Document& document, std::span<const std::string_view> known,
                  std::span<const std::string_view> single, Diagnostics& diagnostics);

std::optional<TrackFileVersion> readTrackVersion(const Document& document, Diagnostics* diagnostics);
void writeTrackVersion(Document& document, const std::optional<TrackFileVersion>& version);
// "version": {"major", "minor"} or null.
void writeVersionJson(JsonWriter& json, const std::optional<TrackFileVersion>& version);

// True for an item that was not read from a file (its kept record is empty).
inline bool isNewRecord(const Node& source) {
    return source.kind() == Node::Kind::Root;
}
// The item's record to edit: a copy of the one it was read from, or a new one.
Node editableRecord(const Node& source, const Document& document, std::string_view keyword);
// Puts the record in place of the first record with its keyword (or adds it); later copies, which
// readers ignore, stay as they are.
void replaceFirstRecord(Document& document, std::string_view keyword, Node record);
// Replaces the records with this keyword unless they are already exactly these, so that writing an
// unchanged model never moves records that were interleaved with others.
void replaceRecordsIfChanged(Document& document, std::string_view keyword, std::vector<Node> records);
// The same with the record `write(item)` makes of each item, in order.
template <class Item, class Write>
void writeRecordsIfChanged(Document& document, std::string_view keyword, const std::vector<Item>& items,
                           Write write) {
    std::vector<Node> records;
    records.reserve(items.size());
    for (const Item& item : items)
        records.push_back(write(item));
    replaceRecordsIfChanged(document, keyword, std::move(records));
}

} // namespace stellwerk::cs2config
