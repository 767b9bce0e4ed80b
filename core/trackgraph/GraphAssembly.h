#pragma once

#include "trackgraph/BlockNaming.h"
#include "trackgraph/BlockPieces.h"
#include "trackgraph/TrackGraph.h"
#include "trackgraph/WaySearch.h"

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace stellwerk::trackgraph {

// Derives a TrackGraph step by step: tiles and page links, stretches, block pieces, pieces merged into
// blocks by their contacts (the same contact drawn on several pages is one block), the ways between them,
// and the checks of drawings and routes.
class GraphAssembly {
public:
    explicit GraphAssembly(const GraphSource& source) : source_(source) {}

    TrackGraph run();

private:
    // Pieces and their blocks (GraphAssembly.cpp).
    void cutPieces();
    void groupPieces();
    std::vector<std::uint32_t> piecesInOrder(std::vector<std::uint32_t> group);
    void indexPieceEnds();
    void searchWays();
    void orientPieces();
    bool runsAlong(std::uint32_t piece, std::uint32_t reference) const;
    std::vector<std::uint32_t> blocksReached(PieceSide side) const;
    BlockEnd blockEndOf(PieceSide side) const;
    std::vector<ContactKey> contactsOf(std::uint32_t piece) const;   // in the order of its steps
    std::vector<TrackStep> orientedSteps(std::uint32_t piece) const; // from its end a to its end b

    // Blocks (GraphBlocks.cpp).
    void buildBlocks();
    Block buildBlock(std::size_t index) const;
    void addContacts(Block& block, const std::vector<std::uint32_t>& pieces) const;
    void addSignals(Block& block) const;
    void indexBlocks();
    void checkDrawings();
    void compareDrawings(std::uint32_t piece, std::uint32_t reference);
    std::string drawingDifference(std::uint32_t piece, std::uint32_t reference) const;
    std::string neighbours(std::uint32_t piece, End end) const;

    // Connections (GraphConnections.cpp).
    void buildConnections();
    Connection connectionOf(const RawWay& way) const;
    void checkTurnoutDrawings();
    std::string describeJoins(const std::set<std::tuple<int, int, int>>& joins, TurnoutKind kind) const;
    void checkRoutes();
    void checkRoute(const cs2config::Route& route, const std::vector<std::int64_t>& turnoutArticles);
    void reportRoute(const cs2config::Route& route, const std::map<std::int64_t, int>& settings);
    void findConflicts();

    const GraphSource& source_;
    TrackGraph graph_;
    ProblemList problems_;
    std::vector<Stretch> stretches_;
    std::vector<BlockPiece> pieces_;
    std::vector<std::uint32_t> blockOfPiece_;
    std::vector<std::uint32_t> referenceOf_; // the piece a piece was oriented by (itself when first)
    std::vector<bool> flipped_;              // true when a piece's side 0 is its block's end b
    std::vector<std::vector<std::uint32_t>> piecesOfBlock_;
    PieceEndIndex pieceEnds_;
    std::vector<RawWay> ways_;
    std::vector<std::vector<std::uint32_t>> waysFrom_; // per piece side (2 * piece + side)
};

} // namespace stellwerk::trackgraph
