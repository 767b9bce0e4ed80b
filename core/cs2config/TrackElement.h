#pragma once

#include "cs2config/Diagnostics.h"
#include "cs2config/Document.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/Node.h"
#include "cs2config/TrackElementType.h"
#include "cs2config/TrackPosition.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// One tile of a track plan page (an `element` record), typed, with its record kept for writing back.
struct TrackElement {
    static constexpr std::string_view keyword = "element";

    TrackPosition position;    // `.id`; a missing `.id` means page 0, column 0, row 0
    std::string type;          // `.typ` as written; empty for a text-only element
    int rotation = 0;          // `.drehung`: clockwise quarter turns, 0..3
    std::int64_t article = -1; // `.artikel`: see articleLink(); -1 = not linked
    std::string text;          // `.text`: the label
    std::int64_t deviceId = 0; // `.deviceId`: the feedback device of an s88 tile (0x100 ...); 0 = none
    std::int64_t state = 0;    // `.zustand`: the position the station showed when it saved the page
    Node source;               // the record as read; empty for a new element

    // The known type, the `text` type for an element without `.typ`, null for an unknown word.
    const TrackElementType* elementType() const;
    TrackCategory category() const;
    ArticleLink articleLink() const;
    bool switchable() const;
    bool hasArticle() const { return article >= 0; }
    // The keyboard id of the article an accessory tile switches: `.artikel` = 2 x the article's `.id`,
    // plus 1 for the second output of a paired article (field notes); nullopt for other tiles.
    std::optional<std::int64_t> accessoryId() const;
    // True when `.artikel` names the second output of its keyboard id (`.ungerade=1` articles).
    bool onSecondOutput() const { return article >= 0 && article % 2 == 1; }
    // The line of the record in its file; 0 for a new element.
    int line() const { return source.lineNumber(); }
};

// Reads the `element` records of one file: typed values, unknown types and keys (once each), missing
// `.id`s (once per file) and elements that share a position.
class TrackElementReader {
public:
    explicit TrackElementReader(Diagnostics& diagnostics) : diagnostics_(diagnostics) {}

    std::vector<TrackElement> read(const std::vector<const Node*>& records);
    // The element a record holds, without any reporting (what the writer compares against).
    static TrackElement decode(const Node& record);

private:
    void reportMissingIds(const std::vector<TrackElement>& elements);
    void reportSharedPositions(const std::vector<TrackElement>& elements);

    Diagnostics& diagnostics_;
};

// Writes an element into a copy of its record, changing only the lines whose value changed; a new
// element gets a record written the way a CS2 writes one.
class TrackElementWriter {
public:
    explicit TrackElementWriter(const Document& document) : document_(document) {}

    Node write(const TrackElement& element) const;

private:
    const Document& document_;
};

// {"line", "page", "column", "row", "id", "type", "category", ...} for `stellwerk-cli cs2 json`.
void writeJson(JsonWriter& json, const TrackElement& element);

} // namespace stellwerk::cs2config
