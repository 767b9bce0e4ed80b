#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/RouteFile.h"
#include "cs2config/TrackLayout.h"
#include "trackgraph/PageLinks.h"
#include "trackgraph/Problem.h"
#include "trackgraph/Stretches.h"
#include "trackgraph/TileShape.h"
#include "trackgraph/TrackTiles.h"

#include <array>
#include <compare>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::trackgraph {

// The two ends of a block. End a is the end whose tile comes first in (page, row, column) order on the
// block's first drawing (the page's number, then row, then column; of two ends on one tile, the one whose
// side comes first clockwise from north); end b is the other.
enum class End : std::uint8_t { A, B };

inline End otherEnd(End end) {
    return end == End::A ? End::B : End::A;
}
// "a" or "b".
std::string_view endName(End end);

// One end of one block. Block ids count from 1 in the order of their end a tiles.
struct BlockEnd {
    int block = 0;
    End end = End::A;

    friend auto operator<=>(const BlockEnd&, const BlockEnd&) = default;
};

// What lies beyond a block end.
enum class EndKind : std::uint8_t {
    Junction,   // a turnout or crossing, or track without contact leading to one
    Block,      // the next block, right there
    BufferStop, // the track ends at a buffer stop (with no turnout between)
    Turntable,  // a turntable or transfer table
    OpenEnd,    // the track ends without a buffer stop (a problem)
};
std::string_view endKindName(EndKind kind);

struct BlockEndInfo {
    TileId tile = 0;       // the block's last tile at this end
    Port port = Port::End; // the side a train leaves the block through
    EndKind beyond = EndKind::OpenEnd;
};

// A feedback contact on a block: the track its tiles cover, in millimetres from end a.
struct ContactOnBlock {
    ContactKey contact;
    TileId tile = 0;   // its first tile from end a
    std::string label; // the tile's `.text`
    int fromMm = 0;
    int toMm = 0;
};

// A signal beside a block or a connection.
struct SignalOnTrack {
    TileId tile = 0;
    std::optional<std::int64_t> article; // its keyboard number
    std::string name;                    // the tile's `.text`, else the article's name in magnetartikel.cs2
    End towards = End::B;                // on a block: the end the trains it faces are running to
    bool facesTravel = true; // on a connection: whether it faces trains running from `from` to `to`
    int atMm = 0;            // the middle of its tile, from end a (or from the connection's start)
};

// A stretch of track that a train on it can be seen on: between turnouts, crossings, buffer stops and
// open ends, around one feedback contact, or several drawn side by side. Two contacts with track between
// them are two blocks, cut at a signal between them (the block whose trains the signal holds keeps it),
// else halfway.
struct Block {
    int id = 0;
    std::string
        name; // a contact's label, else a route button, label or signal beside it, else "Block <contact>"
    std::vector<ContactOnBlock> contacts; // in order from end a
    std::vector<TrackStep> path;          // from end a to end b, on the block's first drawing
    std::vector<TileId> tiles;            // every tile of every drawing of it, sorted
    std::array<BlockEndInfo, 2> ends;
    std::vector<SignalOnTrack> signalsAlong; // in order from end a (not `signals`: a Qt keyword)
    int lengthMm = 0;

    int lengthTiles() const { return int(path.size()); }
    const BlockEndInfo& end(End which) const { return ends[std::size_t(which)]; }
};

// A turnout a connection passes, and the position it needs there.
struct TurnoutOnWay {
    TileId tile = 0;
    std::optional<std::int64_t> article; // the keyboard number; none when the tile names no article
    TurnoutKind kind = TurnoutKind::TwoWay;
    int position = 0;         // the keyboard's position number (Railway::switchAccessory)
    std::uint8_t legMask = 0; // every position that sets the leg passed (a two-drive slip has two)
    bool facing = true;       // entered at its points (choosing the way) rather than trailing
};

// One way from a block end to the next block end without passing another block: the tiles between (none
// where two blocks meet), each turnout with its position, and the crossings passed.
struct Connection {
    int id = 0;
    BlockEnd from;
    BlockEnd to;
    std::vector<TrackStep> path;
    std::vector<TurnoutOnWay> turnouts; // in the order passed
    std::vector<TileId> crossings;      // at grade: a connection over the same crossing conflicts
    std::vector<SignalOnTrack> signalsAlong;
    std::vector<std::int64_t> routes; // ids of fahrstrassen.cs2 routes that set every turnout of it
    std::vector<int> conflicts;       // connections that share a tile with it or need a turnout otherwise
    int lengthMm = 0;
};

// Where the track leads from a block end, with the turnouts as they stand.
enum class LeadKind : std::uint8_t {
    Block,      // to the block end `reached`
    BufferStop, // into a buffer stop
    Turntable,
    OpenEnd,    // off the end of the track
    SetAgainst, // into a turnout set against the train: trailing through it, or a slip set for other legs
    NotSet,     // into a turnout whose position is not known (moving, or not switchable)
    TooLong,    // round a loop without any block
};

struct Lead {
    LeadKind kind = LeadKind::OpenEnd;
    BlockEnd reached;              // Block: the end of the block the train enters
    std::vector<TrackStep> path;   // the tiles passed before that (the turnout itself excluded)
    std::optional<TileId> turnout; // SetAgainst, NotSet: the turnout
    std::optional<std::int64_t> article;
    bool facing = false; // SetAgainst, NotSet: the train met its points (else it runs through it trailing)
};

// A turnout's position by keyboard number; nullopt while it is not known or moving.
using PositionOf = std::function<std::optional<int>(std::int64_t article)>;

// Everything the derivation reads: the pages, and optionally magnetartikel.cs2 (names) and
// fahrstrassen.cs2 (routes checked against the connections).
struct GraphSource {
    std::vector<SourcePage> pages;
    const cs2config::AccessoryFile* accessories = nullptr;
    const cs2config::RouteFile* routes = nullptr;

    // The loaded pages of a layout (a page whose file is missing is known but has no tiles).
    static GraphSource of(const cs2config::TrackLayout& layout,
                          const cs2config::AccessoryFile* accessories = nullptr,
                          const cs2config::RouteFile* routes = nullptr);
};

// The railway a Central Station's track plan shows: its blocks, the connections between them and what is
// wrong with the drawing. Derived once from the files; the same files give the same ids and order.
class TrackGraph {
public:
    static TrackGraph derive(const GraphSource& source);
    static TrackGraph derive(const cs2config::TrackLayout& layout,
                             const cs2config::AccessoryFile* accessories = nullptr,
                             const cs2config::RouteFile* routes = nullptr);

    const std::vector<GraphPage>& pages() const { return tiles_.pages(); }
    const TrackTiles& tiles() const { return tiles_; }
    const Tile& tile(TileId id) const { return tiles_.tile(id); }
    const std::vector<Block>& blocks() const { return blocks_; }
    const Block& block(int id) const { return blocks_[std::size_t(id - 1)]; }
    const std::vector<Connection>& connections() const { return connections_; }
    const Connection& connection(int id) const { return connections_[std::size_t(id - 1)]; }
    const std::vector<Problem>& problems() const { return problems_; }

    // The blocks a tile belongs to (two where a tile carries two tracks); empty for other tiles.
    std::vector<int> blocksAt(TileId tile) const;
    std::optional<TileId> tileAt(const TilePlace& place) const;
    // The block holding a contact; nullopt when no block does.
    std::optional<int> blockWithContact(const ContactKey& contact) const;
    // The connections leaving a block end, in id order.
    std::vector<int> connectionsFrom(const BlockEnd& end) const;
    // The problems on a tile.
    std::vector<const Problem*> problemsAt(TileId tile) const;

    // Where a train leaving the block through `from` runs with the turnouts where `positionOf` says (an
    // open end for a block that does not exist).
    Lead follow(const BlockEnd& from, const PositionOf& positionOf) const;
    // The same from any tile: where a train leaving `tile` through `exit` runs (the simulator follows the
    // track from the tile a train's front is on).
    Lead followFrom(TileId tile, Port exit, const PositionOf& positionOf) const;
    // The block end a train leaving a tile through a port enters right there, if any.
    std::optional<BlockEnd> blockEndAt(TileId tile, Port port) const;

private:
    friend class GraphAssembly;

    TrackTiles tiles_;
    PageLinks links_;
    std::vector<Block> blocks_;
    std::vector<Connection> connections_;
    std::vector<Problem> problems_;
    std::vector<std::array<int, 2>> tileBlocks_;               // per tile, 0 = none
    std::vector<std::pair<std::uint32_t, BlockEnd>> endIndex_; // (tile << 4 | port) -> end, sorted
};

} // namespace stellwerk::trackgraph
