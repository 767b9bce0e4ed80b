#include "trackgraph/GraphAssembly.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <tuple>

namespace stellwerk::trackgraph {

namespace {

auto endKey(const BlockPiece& piece) {
    const PieceEnd& a = piece.ends[std::size_t(piece.sideA())];
    return std::tuple(a.tile, a.port);
}

bool sharesContact(const std::vector<ContactKey>& sortedA, const std::vector<ContactKey>& sortedB) {
    auto a = sortedA.begin();
    auto b = sortedB.begin();
    while (a != sortedA.end() && b != sortedB.end()) {
        if (*a == *b)
            return true;
        *a < *b ? ++a : ++b;
    }
    return false;
}

std::size_t overlap(const std::vector<std::uint32_t>& sortedA, const std::vector<std::uint32_t>& sortedB) {
    std::vector<std::uint32_t> common;
    std::set_intersection(sortedA.begin(), sortedA.end(), sortedB.begin(), sortedB.end(),
                          std::back_inserter(common));
    return common.size();
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t p) {
    while (parent[p] != p)
        p = parent[p] = parent[parent[p]];
    return p;
}

} // namespace

TrackGraph GraphAssembly::run() {
    graph_.tiles_ = TrackTiles::of(source_.pages);
    graph_.links_ = PageLinks::pair(graph_.tiles_, problems_);
    cutPieces();
    groupPieces();
    indexPieceEnds();
    searchWays();
    orientPieces();
    buildBlocks();
    checkDrawings();
    buildConnections();
    checkTurnoutDrawings();
    checkRoutes();
    findConflicts();
    graph_.problems_ = problems_.take();
    return std::move(graph_);
}

void GraphAssembly::cutPieces() {
    const TrackJoints joints(graph_.tiles_, graph_.links_);
    const Stretches stretches(joints);
    stretches.reportLooseEnds(problems_);
    pieces_ = BlockCutter(graph_.tiles_, problems_).cut(stretches.trace());
}

// Pieces that share a contact are one block; blocks are numbered by their end a.
void GraphAssembly::groupPieces() {
    std::vector<std::uint32_t> parent(pieces_.size());
    std::iota(parent.begin(), parent.end(), 0U);
    std::map<ContactKey, std::uint32_t> firstWith;
    for (std::uint32_t p = 0; p < pieces_.size(); ++p)
        for (const ContactKey& key : contactsOf(p)) {
            const auto [found, fresh] = firstWith.emplace(key, p);
            if (!fresh)
                parent[findRoot(parent, p)] = findRoot(parent, found->second);
        }
    std::map<std::uint32_t, std::vector<std::uint32_t>> groups;
    for (std::uint32_t p = 0; p < pieces_.size(); ++p)
        groups[findRoot(parent, p)].push_back(p);
    referenceOf_.assign(pieces_.size(), 0);
    for (auto& [root, group] : groups)
        piecesOfBlock_.push_back(piecesInOrder(std::move(group)));
    std::sort(piecesOfBlock_.begin(), piecesOfBlock_.end(), [this](const auto& a, const auto& b) {
        return endKey(pieces_[a.front()]) < endKey(pieces_[b.front()]);
    });
    blockOfPiece_.assign(pieces_.size(), 0);
    for (std::uint32_t block = 0; block < piecesOfBlock_.size(); ++block)
        for (const std::uint32_t p : piecesOfBlock_[block])
            blockOfPiece_[p] = block;
}

// The block's first drawing (its end a first in plan order), then each piece after one it shares a
// contact with, which it is oriented by and compared with.
std::vector<std::uint32_t> GraphAssembly::piecesInOrder(std::vector<std::uint32_t> group) {
    std::map<std::uint32_t, std::vector<ContactKey>> keys;
    for (const std::uint32_t p : group) {
        keys[p] = contactsOf(p);
        std::sort(keys[p].begin(), keys[p].end());
    }
    const auto first = std::min_element(group.begin(), group.end(), [this](std::uint32_t a, std::uint32_t b) {
        return endKey(pieces_[a]) < endKey(pieces_[b]);
    });
    std::vector<std::uint32_t> ordered{*first};
    referenceOf_[*first] = *first;
    group.erase(first);
    for (std::size_t next = 0; next < ordered.size() && !group.empty(); ++next)
        for (auto it = group.begin(); it != group.end();) {
            if (!sharesContact(keys[*it], keys[ordered[next]])) {
                ++it;
                continue;
            }
            referenceOf_[*it] = ordered[next];
            ordered.push_back(*it);
            it = group.erase(it);
        }
    return ordered;
}

void GraphAssembly::indexPieceEnds() {
    for (std::uint32_t p = 0; p < pieces_.size(); ++p)
        for (std::uint8_t side = 0; side < 2; ++side)
            pieceEnds_.add(pieces_[p].ends[side].tile, pieces_[p].ends[side].port, {p, side});
    pieceEnds_.sort();
}

void GraphAssembly::searchWays() {
    const TrackJoints joints(graph_.tiles_, graph_.links_);
    WaySearch search(joints, pieceEnds_, problems_);
    waysFrom_.assign(2 * pieces_.size(), {});
    for (std::uint32_t p = 0; p < pieces_.size(); ++p)
        for (std::uint8_t side = 0; side < 2; ++side) {
            const std::size_t before = ways_.size();
            search.from({p, side}, pieces_[p].ends[side].tile, pieces_[p].ends[side].port, ways_);
            for (std::size_t w = before; w < ways_.size(); ++w)
                waysFrom_[2 * p + side].push_back(std::uint32_t(w));
        }
}

void GraphAssembly::orientPieces() {
    flipped_.assign(pieces_.size(), false);
    for (const std::vector<std::uint32_t>& pieces : piecesOfBlock_)
        for (const std::uint32_t p : pieces) {
            const std::uint32_t reference = referenceOf_[p];
            if (reference == p)
                flipped_[p] = pieces_[p].sideA() == 1;
            else
                flipped_[p] = runsAlong(p, reference) ? flipped_[reference] : !flipped_[reference];
        }
}

// Whether two drawings of a block run the same way: by the order of two contacts both hold, else by the
// blocks their ends lead to, else by their own ends a.
bool GraphAssembly::runsAlong(std::uint32_t piece, std::uint32_t reference) const {
    const std::vector<ContactKey> mine = contactsOf(piece);
    const std::vector<ContactKey> theirs = contactsOf(reference);
    std::vector<std::size_t> order; // where the contacts of `theirs` lie in `mine`
    for (const ContactKey& key : theirs) {
        const auto found = std::find(mine.begin(), mine.end(), key);
        if (found != mine.end() && std::find(order.begin(), order.end(), found - mine.begin()) == order.end())
            order.push_back(std::size_t(found - mine.begin()));
    }
    if (order.size() >= 2)
        return order[0] < order[1];
    const std::size_t same = overlap(blocksReached({piece, 0}), blocksReached({reference, 0})) +
                             overlap(blocksReached({piece, 1}), blocksReached({reference, 1}));
    const std::size_t crossed = overlap(blocksReached({piece, 0}), blocksReached({reference, 1})) +
                                overlap(blocksReached({piece, 1}), blocksReached({reference, 0}));
    if (same != crossed)
        return same > crossed;
    return pieces_[piece].sideA() == pieces_[reference].sideA();
}

std::vector<std::uint32_t> GraphAssembly::blocksReached(PieceSide side) const {
    std::vector<std::uint32_t> blocks;
    for (const std::uint32_t way : waysFrom_[2 * side.piece + side.side])
        blocks.push_back(blockOfPiece_[ways_[way].to.piece]);
    std::sort(blocks.begin(), blocks.end());
    blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
    return blocks;
}

BlockEnd GraphAssembly::blockEndOf(PieceSide side) const {
    const bool a = (side.side == 0) != flipped_[side.piece];
    return {int(blockOfPiece_[side.piece]) + 1, a ? End::A : End::B};
}

std::vector<ContactKey> GraphAssembly::contactsOf(std::uint32_t piece) const {
    std::vector<ContactKey> keys;
    for (const std::size_t step : pieces_[piece].contactSteps) {
        const ContactKey key = *graph_.tiles_.tile(pieces_[piece].steps[step].tile).contact;
        if (keys.empty() || keys.back() != key)
            keys.push_back(key);
    }
    return keys;
}

std::vector<TrackStep> GraphAssembly::orientedSteps(std::uint32_t piece) const {
    std::vector<TrackStep> steps = pieces_[piece].steps;
    if (flipped_[piece]) {
        std::reverse(steps.begin(), steps.end());
        for (TrackStep& step : steps)
            std::swap(step.entry, step.exit);
    }
    return steps;
}

} // namespace stellwerk::trackgraph
