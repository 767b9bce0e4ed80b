#pragma once

#include "model/TrackLayout.h"
#include "trackgraph/TrackGraph.h"

#include <memory>
#include <optional>
#include <vector>

namespace stellwerk::ui {

// The track graph of the layout in use (derived there, once per layout) with the plan's tiles (page index,
// tile index) translated to the graph's and back. The plan keeps one and hands it to its page views and its
// block popup.
class PlanGraph final {
public:
    // The tiles of `graph`, which must have been derived from the pages `shown` was made from (same
    // numbers, same order); null when it was not, or there is no graph.
    static std::shared_ptr<const PlanGraph> of(std::shared_ptr<const trackgraph::TrackGraph> graph,
                                               const model::TrackLayout& shown);

    const trackgraph::TrackGraph& graph() const { return *m_graph; }
    std::optional<trackgraph::TileId> graphTile(model::TileRef tile) const;
    std::optional<model::TileRef> planTile(trackgraph::TileId tile) const;
    // The blocks a plan tile belongs to (none for a turnout, a label, ...).
    std::vector<int> blocksAt(model::TileRef tile) const;
    // The problems on a plan tile.
    std::vector<const trackgraph::Problem*> problemsAt(model::TileRef tile) const;
    // The tiles of one page (plan tile indexes) that carry a problem, each once, in the page's order.
    std::vector<int> problemTilesOf(int page) const;

private:
    PlanGraph(std::shared_ptr<const trackgraph::TrackGraph> graph, const model::TrackLayout& shown);

    std::shared_ptr<const trackgraph::TrackGraph> m_graph;
    // Per plan page, per plan tile: the graph's tile; and per graph tile, the first plan tile drawing it.
    std::vector<std::vector<std::optional<trackgraph::TileId>>> m_graphTiles;
    std::vector<std::optional<model::TileRef>> m_planTiles;
};

} // namespace stellwerk::ui
