#include "trackgraph/BlockPieces.h"

#include <algorithm>
#include <tuple>

namespace stellwerk::trackgraph {

int BlockPiece::sideA() const {
    return std::tuple(ends[1].tile, ends[1].port) < std::tuple(ends[0].tile, ends[0].port) ? 1 : 0;
}

std::vector<BlockPiece> BlockCutter::cut(const std::vector<Stretch>& stretches) {
    std::vector<BlockPiece> pieces;
    for (const Stretch& stretch : stretches)
        cutStretch(stretch, pieces);
    return pieces;
}

void BlockCutter::cutStretch(const Stretch& stretch, std::vector<BlockPiece>& pieces) {
    const std::vector<TrackStep> steps = stretch.loop ? loopInOrder(stretch) : stretch.steps;
    const std::vector<Group> groups = groupsOf(steps);
    if (groups.empty())
        return reportWithoutContact(stretch);
    const auto firstPiece = std::uint32_t(pieces.size());
    const auto lastPiece = std::uint32_t(firstPiece + groups.size() - 1);
    std::size_t begin = 0;
    for (std::size_t i = 0; i < groups.size(); ++i) {
        const bool last = i + 1 == groups.size();
        const std::size_t end =
            last ? steps.size() : cutBetween(steps, groups[i].last + 1, groups[i + 1].first);
        BlockPiece piece;
        piece.steps.assign(steps.begin() + std::ptrdiff_t(begin), steps.begin() + std::ptrdiff_t(end));
        for (std::size_t k = 0; k < piece.steps.size(); ++k)
            if (isContact(piece.steps[k]))
                piece.contactSteps.push_back(k);
        const auto index = std::uint32_t(pieces.size());
        piece.ends[0] = {piece.steps.front().tile, piece.steps.front().entry,
                         i == 0 ? stretch.first : StretchEnd{},
                         i > 0          ? std::optional(index - 1)
                         : stretch.loop ? std::optional(lastPiece)
                                        : std::nullopt};
        piece.ends[1] = {piece.steps.back().tile, piece.steps.back().exit, last ? stretch.last : StretchEnd{},
                         !last          ? std::optional(index + 1)
                         : stretch.loop ? std::optional(firstPiece)
                                        : std::nullopt};
        pieces.push_back(std::move(piece));
        begin = end;
    }
}

std::vector<BlockCutter::Group> BlockCutter::groupsOf(const std::vector<TrackStep>& steps) const {
    std::vector<Group> groups;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (!isContact(steps[i]))
            continue;
        if (!groups.empty() && groups.back().last + 1 == i)
            groups.back().last = i;
        else
            groups.push_back({i, i});
    }
    return groups;
}

// A signal between two blocks ends the block its trains wait in: one facing the trains that come from the
// earlier block belongs to it, one facing the other way to the later block. Without a signal, halfway.
std::size_t BlockCutter::cutBetween(const std::vector<TrackStep>& steps, std::size_t begin,
                                    std::size_t end) const {
    std::optional<std::size_t> lastFacingOn;
    std::optional<std::size_t> firstFacingBack;
    for (std::size_t k = begin; k < end; ++k) {
        const Tile& tile = tiles_.tile(steps[k].tile);
        if (tile.role() != TileRole::Signal)
            continue;
        if (steps[k].entry == tile.shape.signalApproach)
            lastFacingOn = k;
        else if (!firstFacingBack)
            firstFacingBack = k;
    }
    if (lastFacingOn)
        return *lastFacingOn + 1;
    if (firstFacingBack)
        return *firstFacingBack;
    return begin + (end - begin + 1) / 2;
}

// A loop's steps turned so that they begin where its last block meets its first.
std::vector<TrackStep> BlockCutter::loopInOrder(const Stretch& loop) const {
    std::vector<TrackStep> steps = loop.steps;
    const std::size_t n = steps.size();
    std::size_t start = n;
    for (std::size_t i = 0; i < n && start == n; ++i)
        if (isContact(steps[i]) && !isContact(steps[(i + n - 1) % n]))
            start = i;
    if (start == n)
        return steps; // no contact, or nothing but contacts
    std::rotate(steps.begin(), steps.begin() + std::ptrdiff_t(start), steps.end());
    const std::size_t cut = cutBetween(steps, groupsOf(steps).back().last + 1, n);
    std::rotate(steps.begin(), steps.begin() + std::ptrdiff_t(cut), steps.end());
    return steps;
}

void BlockCutter::reportWithoutContact(const Stretch& stretch) {
    TileId first = stretch.steps.front().tile;
    for (const TrackStep& step : stretch.steps)
        first = std::min(first, step.tile);
    const std::size_t n = stretch.steps.size();
    const std::string ends = " between " + describeStretchEnd(tiles_, stretch.first) + " and " +
                             describeStretchEnd(tiles_, stretch.last);
    const std::string where = stretch.loop ? "This loop of " + std::to_string(n) + " tiles has"
                              : n == 1     ? "This tile of track" + ends + " has"
                                       : "These " + std::to_string(n) + " tiles of track" + ends + " have";
    problems_.add(ProblemKind::NoContact, first,
                  where +
                      " no contact, so a train there cannot be seen; add a contact where trains may stop.");
}

std::string describeStretchEnd(const TrackTiles& tiles, const StretchEnd& end) {
    switch (end.kind) {
    case StretchEndKind::Junction: {
        const Tile& tile = tiles.tile(end.junction);
        const std::string place =
            "column " + std::to_string(tile.place.column) + ", row " + std::to_string(tile.place.row);
        if (tile.role() == TileRole::Crossing)
            return "the crossing at " + place;
        return tile.accessory ? "turnout " + std::to_string(*tile.accessory) : "the turnout at " + place;
    }
    case StretchEndKind::BufferStop:
        return "a buffer stop";
    case StretchEndKind::Turntable:
        return "a turntable";
    case StretchEndKind::OpenEnd:
        break;
    }
    return "an open end";
}

} // namespace stellwerk::trackgraph
