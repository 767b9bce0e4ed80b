#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace stellwerk::trackgraph {

// Where track leaves a tile: the middle of a side, a corner (the scissors crossing's diagonals), the link
// of a page arrow to its partner on another page, or nowhere (the track ends inside the tile: a buffer stop,
// a turntable's approach). Numbered clockwise from north, so that a quarter turn adds two.
enum class Port : std::uint8_t {
    North,
    NorthEast,
    East,
    SouthEast,
    South,
    SouthWest,
    West,
    NorthWest,
    Link,
    End
};

inline constexpr int GeometricPorts = 8;

bool isGeometric(Port port);
// The port after `quarterTurns` quarter turns counter-clockwise on screen, as the plan's painter turns a
// tile by its `.drehung` (ui/trackplan TileCanvas::unit); Link and End stay.
Port rotated(Port port, int quarterTurns);
// The port of the neighbouring tile that touches this one: south for north, south-west for north-east...
Port facing(Port port);
// Column and row step to the tile beyond a geometric port (north: 0, -1).
std::array<int, 2> offsetOf(Port port);
// "north", "north-east", ..., "link to another page", "end" (for problem sentences and the CLI).
std::string_view portName(Port port);

// What a tile is for the graph.
enum class TileRole : std::uint8_t {
    None,     // not track: labels, buttons, lamps, outputs beside the track, unknown types
    Track,    // plain track, also uncouplers and level crossings lying on it
    Contact,  // an S88 feedback contact on the track
    Signal,   // a signal beside the track
    Turnout,  // points and slips: legs set by a position
    Crossing, // two tracks crossing at grade: always passable, but connections over it conflict
    BufferStop,
    PageLink,  // a page arrow (`pfeil`): the track goes on at the arrow it is paired with
    Turntable, // turntables and transfer tables: the graph ends at their approach
};

// The kinds of turnout, for the names of their positions.
enum class TurnoutKind : std::uint8_t {
    None,
    TwoWay,              // left and right turnouts: 0 diverging, 1 straight
    Y,                   // 0 left, 1 right
    ThreeWay,            // 0 left, 1 straight, 2 right
    DoubleSlip,          // one drive: 0 both curves, 1 both straights
    DoubleSlipTwoDrives, // 0 diverging, 1 straight, 2 straight+diverging, 3 diverging+straight (keyboard)
    ThreeWaySlip,        // 0 diverging, 1 straight, 2 the crossing straight
    Scissors,            // 0 both diagonals, 1 straight
};

// One piece of track inside a tile, between two ports, with the turnout positions that set it (a bit per
// position; 0 for track that is always there). Legs of one tile that share a port or cross at grade make
// the tile a junction.
struct Leg {
    Port from;
    Port to;
    std::uint8_t positions = 0;

    bool always() const { return positions == 0; }
    bool setIn(int position) const;
    // The position a connection over this leg asks for: the lowest that sets it (0 for plain track).
    int position() const;
    bool touches(Port port) const { return from == port || to == port; }
    Port otherEnd(Port port) const { return port == from ? to : from; }
    // Millimetres along the leg: 180 across a tile, 141 on a quarter curve, 255 corner to corner, 90 from a
    // side to the tile's middle (buffer stop, turntable) or to a page arrow's link.
    int lengthMm() const;
};

// The track a tile type carries, unrotated (as the plan draws it with `.drehung=0`).
struct TileShape {
    TileRole role = TileRole::None;
    TurnoutKind turnout = TurnoutKind::None;
    std::array<Leg, 4> legArray{};
    std::uint8_t legCount = 0;
    // The side trains come from when a signal faces them (unrotated: west).
    Port signalApproach = Port::West;

    std::span<const Leg> legs() const { return {legArray.data(), legCount}; }
    bool isJunction() const { return role == TileRole::Turnout || role == TileRole::Crossing; }
    bool isTrack() const { return legCount > 0; }
};

// The shape of a `.typ` word (the painter's table, ui/trackplan/TrackTilePainter.cpp, decides by the same
// words and prefixes); a shape without legs for everything that is not track.
const TileShape& tileShapeOf(std::string_view type);
// The shape turned by `.drehung` quarter turns: every leg's ports and the signal's approach side.
TileShape rotatedShape(const TileShape& shape, int quarterTurns);

// How many positions the keyboard gives a kind of turnout (two for two-way turnouts, four for a two-drive
// slip).
int positionCount(TurnoutKind kind);
// The name of a turnout position for users and JSON: "straight", "diverging", "left", "right"...
std::string_view positionName(TurnoutKind kind, int position);

// Tile lengths, documented in docs/guide/track-graph.md.
inline constexpr int StraightTileMm = 180;
inline constexpr int CurveTileMm = 141;
inline constexpr int DiagonalTileMm = 255;
inline constexpr int HalfTileMm = 90;

} // namespace stellwerk::trackgraph
