#pragma once

#include <QCoreApplication>
#include <QString>

namespace stellwerk::trackgraph {
class TrackGraph;
struct Problem;
struct Tile;
} // namespace stellwerk::trackgraph

namespace stellwerk::ui {

// Says a problem of the track graph in the language chosen: one sentence per kind of problem, with the
// page, column and row and the names its tile carries (the graph's own sentences are English, for the
// command line).
class GraphProblemText final {
    Q_DECLARE_TR_FUNCTIONS(GraphProblemText)

public:
    // "Page 'Bw', column 3, row 1: ..." for the problems bar.
    static QString of(const trackgraph::TrackGraph& graph, const trackgraph::Problem& problem);
    // The sentence alone, for the tile's tooltip.
    static QString sentence(const trackgraph::TrackGraph& graph, const trackgraph::Problem& problem);
    // A heading and one line per problem; empty when the graph has none.
    static QString list(const trackgraph::TrackGraph& graph);
    // "'Bw'", or the page's number when it has no name.
    static QString pageName(const trackgraph::TrackGraph& graph, std::uint32_t page);

private:
    static QString pageLinkSentence(const trackgraph::TrackGraph& graph, const trackgraph::Problem& problem);
    static QString drawingSentence(const trackgraph::TrackGraph& graph, const trackgraph::Problem& problem);
    static QString waySentence(const trackgraph::TrackGraph& graph, const trackgraph::Problem& problem);
    static QString typeName(const trackgraph::Tile& tile);
    static QString turnoutName(const trackgraph::Tile& tile);
    static QString contactName(const trackgraph::Tile& tile);
    static QString linkedPage(const trackgraph::TrackGraph& graph, const trackgraph::Tile& arrow);
};

} // namespace stellwerk::ui
