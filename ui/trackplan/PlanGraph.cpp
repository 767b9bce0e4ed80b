#include "trackplan/PlanGraph.h"

#include <algorithm>

namespace stellwerk::ui {
namespace {

// True when the graph's pages are the shown layout's, in the same order.
bool samePages(const trackgraph::TrackGraph& graph, const model::TrackLayout& shown) {
    const std::vector<model::LayoutPage>& pages = shown.pages();
    if (pages.empty() || pages.size() != graph.pages().size())
        return false;
    for (std::size_t i = 0; i < pages.size(); ++i)
        if (pages[i].id != graph.pages()[i].id)
            return false;
    return true;
}

} // namespace

std::shared_ptr<const PlanGraph> PlanGraph::of(std::shared_ptr<const trackgraph::TrackGraph> graph,
                                               const model::TrackLayout& shown) {
    if (!graph || !samePages(*graph, shown))
        return nullptr;
    return std::shared_ptr<const PlanGraph>(new PlanGraph(std::move(graph), shown));
}

PlanGraph::PlanGraph(std::shared_ptr<const trackgraph::TrackGraph> graph, const model::TrackLayout& shown)
    : m_graph(std::move(graph)), m_planTiles(m_graph->tiles().size()) {
    const std::vector<model::LayoutPage>& pages = shown.pages();
    m_graphTiles.resize(pages.size());
    for (int p = 0; p < int(pages.size()); ++p) {
        const model::LayoutPage& page = pages[std::size_t(p)];
        auto& tiles = m_graphTiles[std::size_t(p)];
        tiles.reserve(page.tiles.size());
        for (int t = 0; t < int(page.tiles.size()); ++t) {
            const cs2config::TrackPosition& at = page.tiles[std::size_t(t)].position;
            const std::optional<trackgraph::TileId> id = m_graph->tileAt({page.id, at.column, at.row});
            tiles.push_back(id);
            if (id && !m_planTiles[*id])
                m_planTiles[*id] = model::TileRef{p, t};
        }
    }
}

std::optional<trackgraph::TileId> PlanGraph::graphTile(model::TileRef tile) const {
    if (tile.page < 0 || std::size_t(tile.page) >= m_graphTiles.size())
        return std::nullopt;
    const auto& tiles = m_graphTiles[std::size_t(tile.page)];
    return tile.tile >= 0 && std::size_t(tile.tile) < tiles.size() ? tiles[std::size_t(tile.tile)]
                                                                   : std::nullopt;
}

std::optional<model::TileRef> PlanGraph::planTile(trackgraph::TileId tile) const {
    return tile < m_planTiles.size() ? m_planTiles[tile] : std::nullopt;
}

std::vector<int> PlanGraph::blocksAt(model::TileRef tile) const {
    const std::optional<trackgraph::TileId> id = graphTile(tile);
    return id ? m_graph->blocksAt(*id) : std::vector<int>();
}

std::vector<const trackgraph::Problem*> PlanGraph::problemsAt(model::TileRef tile) const {
    const std::optional<trackgraph::TileId> id = graphTile(tile);
    return id ? m_graph->problemsAt(*id) : std::vector<const trackgraph::Problem*>();
}

std::vector<int> PlanGraph::problemTilesOf(int page) const {
    std::vector<int> tiles;
    for (const trackgraph::Problem& problem : m_graph->problems())
        if (const std::optional<model::TileRef> at = planTile(problem.tile); at && at->page == page)
            tiles.push_back(at->tile);
    std::sort(tiles.begin(), tiles.end());
    tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
    return tiles;
}

} // namespace stellwerk::ui
