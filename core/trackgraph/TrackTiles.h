#pragma once

#include "cs2config/TrackElement.h"
#include "trackgraph/TileShape.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::trackgraph {

using TileId = std::uint32_t;

// A page of the track plan as the graph knows it: its number and name in gleisbild.cs2, and whether its
// file was read.
struct GraphPage {
    std::int64_t id = 0;
    std::string name;
    bool loaded = false;
};

// One page handed to the derivation: its entry in gleisbild.cs2 and its tiles (null when the file was not
// read).
struct SourcePage {
    std::int64_t id = 0;
    std::string name;
    const std::vector<cs2config::TrackElement>* elements = nullptr;
};

// Where a tile is: the page's number (`.id` of its `seite` in gleisbild.cs2), column (x) and row (y).
struct TilePlace {
    std::int64_t page = 0;
    int column = 0;
    int row = 0;

    friend bool operator==(const TilePlace&, const TilePlace&) = default;
};

// An S88 contact as the pages name it: the feedback device (`.deviceId`, 0 for the station's own bus) and
// the contact number (`.artikel` of the tile).
struct ContactKey {
    std::int64_t device = 0;
    std::int64_t number = 0;

    friend auto operator<=>(const ContactKey&, const ContactKey&) = default;
};

// One tile of one page, with the track its type and rotation give it.
struct Tile {
    TilePlace place;
    std::uint32_t page = 0; // index into TrackTiles::pages()
    std::string type;
    int rotation = 0;
    TileShape shape;                       // turned by the rotation
    std::optional<std::int64_t> accessory; // the keyboard number of a turnout, signal or uncoupler
    std::optional<ContactKey> contact;     // an S88 contact tile's contact
    std::int64_t article = -1;             // `.artikel` as written
    std::string text;                      // `.text`

    TileRole role() const { return shape.role; }
};

// Every tile of every page read, ordered by page (number, then the order of gleisbild.cs2), row and
// column, so that a smaller TileId is a tile further up the plan; with a lookup by place. Where a page has
// two tiles on one place, the first in its file counts.
class TrackTiles {
public:
    static TrackTiles of(const std::vector<SourcePage>& pages);

    const std::vector<GraphPage>& pages() const { return pages_; }
    const std::vector<Tile>& tiles() const { return tiles_; }
    const Tile& tile(TileId id) const { return tiles_[id]; }
    std::size_t size() const { return tiles_.size(); }

    // The tile at a place of a page (an index into pages()); nullopt for an empty place.
    std::optional<TileId> at(std::uint32_t page, int column, int row) const;
    // The tile beyond a geometric port of `tile`, whatever it is; nullopt for an empty place.
    std::optional<TileId> beside(TileId tile, Port port) const;
    // The tile beyond a geometric port whose track meets this tile's there; nullopt when no track does.
    std::optional<TileId> joinedAt(TileId tile, Port port) const;
    // The page (index into pages()) with this number, or named so; nullopt when there is none.
    std::optional<std::uint32_t> pageWithId(std::int64_t id) const;
    std::optional<std::uint32_t> pageNamed(std::string_view name) const;

private:
    void addPage(std::uint32_t index, const SourcePage& source);

    std::vector<GraphPage> pages_;
    std::vector<Tile> tiles_;
};

} // namespace stellwerk::trackgraph
