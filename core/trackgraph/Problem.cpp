#include "trackgraph/Problem.h"

#include <algorithm>
#include <tuple>

namespace stellwerk::trackgraph {

std::string_view problemKindName(ProblemKind kind) {
    switch (kind) {
    case ProblemKind::OpenEnd:
        return "open-end";
    case ProblemKind::JoinsNothing:
        return "joins-nothing";
    case ProblemKind::TurnoutLegNowhere:
        return "turnout-leg-nowhere";
    case ProblemKind::PageLinkNoPage:
        return "page-link-no-page";
    case ProblemKind::PageLinkFileMissing:
        return "page-link-file-missing";
    case ProblemKind::PageLinkUnpaired:
        return "page-link-unpaired";
    case ProblemKind::ContactInTwoBlocks:
        return "contact-in-two-blocks";
    case ProblemKind::DrawingsDisagree:
        return "drawings-disagree";
    case ProblemKind::NoContact:
        return "no-contact";
    case ProblemKind::RouteNoConnection:
        return "route-no-connection";
    case ProblemKind::TurnoutClash:
        return "turnout-clash";
    case ProblemKind::TooManyWays:
        break;
    }
    return "too-many-ways";
}

void ProblemList::add(ProblemKind kind, TileId tile, std::string text) {
    problems_.push_back({kind, tile, std::move(text)});
}

std::vector<Problem> ProblemList::take() {
    const auto key = [](const Problem& p) { return std::tie(p.tile, p.kind, p.text); };
    std::sort(problems_.begin(), problems_.end(),
              [&key](const Problem& a, const Problem& b) { return key(a) < key(b); });
    problems_.erase(std::unique(problems_.begin(), problems_.end(),
                                [&key](const Problem& a, const Problem& b) { return key(a) == key(b); }),
                    problems_.end());
    return std::move(problems_);
}

std::string describePage(const GraphPage& page) {
    return page.name.empty() ? std::to_string(page.id) : "'" + page.name + "'";
}

std::string describePlace(const TrackTiles& tiles, TileId tile) {
    const Tile& t = tiles.tile(tile);
    return "page " + describePage(tiles.pages()[t.page]) + ", column " + std::to_string(t.place.column) +
           ", row " + std::to_string(t.place.row);
}

} // namespace stellwerk::trackgraph
