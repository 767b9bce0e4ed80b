#pragma once

#include "trackgraph/TrackTiles.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::trackgraph {

// What is wrong, so that a view can mark it and say it in its own language.
enum class ProblemKind : std::uint8_t {
    OpenEnd,             // track ends without a buffer stop
    JoinsNothing,        // a track tile that no other track joins
    TurnoutLegNowhere,   // a turnout's leg that no track continues
    PageLinkNoPage,      // a page arrow names a page the plan does not have
    PageLinkFileMissing, // the page it names has no file
    PageLinkUnpaired,    // no arrow on the page it names leads back
    ContactInTwoBlocks,  // one contact on two separate stretches of one page
    DrawingsDisagree,    // two pages draw one contact with different neighbours
    NoContact,           // a stretch of track without contact: a train there cannot be seen
    RouteNoConnection,   // a route of fahrstrassen.cs2 whose turnout settings join no two blocks
    TurnoutClash,        // a way that needs one turnout article in two positions
    TooManyWays,         // the search for ways from a block end was cut short
};

// "open-end", "joins-nothing", ... for JSON.
std::string_view problemKindName(ProblemKind kind);

// One problem of the derived graph, on the tile it is about, in a sentence a person can act on.
struct Problem {
    ProblemKind kind = ProblemKind::OpenEnd;
    TileId tile = 0;
    std::string text;
};

// Collects problems while the graph is derived; each tile's problem of one kind and text only once.
class ProblemList {
public:
    void add(ProblemKind kind, TileId tile, std::string text);
    // Sorted by tile (page, row, column), kind and text, without repeats.
    std::vector<Problem> take();

private:
    std::vector<Problem> problems_;
};

// "page 'Bahnhof', column 3, row 4" for sentences.
std::string describePlace(const TrackTiles& tiles, TileId tile);
// "'Bahnhof'" or "3" when the page has no name.
std::string describePage(const GraphPage& page);

} // namespace stellwerk::trackgraph
