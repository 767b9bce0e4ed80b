#include "trackgraph/PageLinks.h"

#include <algorithm>
#include <cstdlib>
#include <tuple>

namespace stellwerk::trackgraph {

namespace {

// The arrow's track side: its only leg's geometric port.
Port trackSide(const Tile& arrow) {
    const Leg& leg = arrow.shape.legs()[0];
    return isGeometric(leg.from) ? leg.from : leg.to;
}

std::string namedPage(const Tile& arrow) {
    if (arrow.article >= 0)
        return "page " + std::to_string(arrow.article) +
               (arrow.text.empty() ? "" : " ('" + arrow.text + "')");
    return "page '" + arrow.text + "'";
}

struct Candidate {
    int distance;
    TileId first;
    TileId second;
};

} // namespace

PageLinks PageLinks::pair(const TrackTiles& tiles, ProblemList& problems) {
    std::vector<Arrow> arrows;
    for (TileId id = 0; id < tiles.size(); ++id)
        if (tiles.tile(id).role() == TileRole::PageLink)
            if (const std::optional<Arrow> arrow = trackArrow(tiles, id, problems))
                arrows.push_back(*arrow);
    PageLinks links;
    links.pairArrows(tiles, arrows);
    for (const Arrow& arrow : arrows)
        if (!links.partnerOf(arrow.tile))
            problems.add(ProblemKind::PageLinkUnpaired, arrow.tile,
                         "The arrow to page " + describePage(tiles.pages()[arrow.to]) +
                             " has no arrow back to page " + describePage(tiles.pages()[arrow.from]) +
                             " there, so the track ends here; add one where the track goes on.");
    return links;
}

std::optional<PageLinks::Arrow> PageLinks::trackArrow(const TrackTiles& tiles, TileId tile,
                                                      ProblemList& problems) {
    const Tile& arrow = tiles.tile(tile);
    if (!tiles.joinedAt(tile, trackSide(arrow)))
        return std::nullopt; // a button for changing pages, not track
    std::optional<std::uint32_t> page;
    if (arrow.article >= 0)
        page = tiles.pageWithId(arrow.article);
    if (!page && !arrow.text.empty())
        page = tiles.pageNamed(arrow.text);
    if (!page) {
        problems.add(ProblemKind::PageLinkNoPage, tile,
                     "The arrow names " + namedPage(arrow) +
                         ", which the track plan does not have; the track ends here.");
        return std::nullopt;
    }
    if (!tiles.pages()[*page].loaded) {
        problems.add(ProblemKind::PageLinkFileMissing, tile,
                     "The arrow leads to page " + describePage(tiles.pages()[*page]) +
                         ", whose file is missing; the track ends here.");
        return std::nullopt;
    }
    return Arrow{tile, arrow.page, *page};
}

void PageLinks::pairArrows(const TrackTiles& tiles, const std::vector<Arrow>& arrows) {
    std::vector<Candidate> candidates;
    for (std::size_t i = 0; i < arrows.size(); ++i)
        for (std::size_t j = i + 1; j < arrows.size(); ++j) {
            if (arrows[i].from != arrows[j].to || arrows[i].to != arrows[j].from)
                continue;
            const TilePlace& a = tiles.tile(arrows[i].tile).place;
            const TilePlace& b = tiles.tile(arrows[j].tile).place;
            const int distance = std::abs(a.column - b.column) + std::abs(a.row - b.row);
            candidates.push_back({distance, arrows[i].tile, arrows[j].tile});
        }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
        return std::tie(x.distance, x.first, x.second) < std::tie(y.distance, y.first, y.second);
    });
    for (const Candidate& candidate : candidates) {
        if (partnerOf(candidate.first) || partnerOf(candidate.second))
            continue;
        partners_.insert(std::upper_bound(partners_.begin(), partners_.end(),
                                          std::pair(candidate.first, candidate.second)),
                         {candidate.first, candidate.second});
        partners_.insert(std::upper_bound(partners_.begin(), partners_.end(),
                                          std::pair(candidate.second, candidate.first)),
                         {candidate.second, candidate.first});
    }
}

std::optional<TileId> PageLinks::partnerOf(TileId arrow) const {
    const auto found = std::lower_bound(partners_.begin(), partners_.end(), std::pair(arrow, TileId{0}));
    if (found == partners_.end() || found->first != arrow)
        return std::nullopt;
    return found->second;
}

} // namespace stellwerk::trackgraph
