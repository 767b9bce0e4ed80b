#pragma once

#include "cs2config/ConfigFile.h"
#include "cs2config/LayoutFolder.h"
#include "cs2config/TrackElement.h"
#include "trackgraph/GraphInvariants.h"
#include "trackgraph/TrackGraph.h"

#include <gtest/gtest.h>
#include <ostream>
#include <string>
#include <vector>

// Pages drawn tile by tile in a test, and what the track graph tests ask of a derived graph.
namespace stellwerk::trackgraph::test {

class DrawnPage {
public:
    DrawnPage(std::int64_t id, std::string name) : id_(id), name_(std::move(name)) {}

    // Any tile: `.typ`, `.drehung`, `.artikel` as the file would write them.
    DrawnPage& tile(int column, int row, const std::string& type, int rotation = 0, std::int64_t article = -1,
                    const std::string& text = {}, std::int64_t device = 0) {
        cs2config::TrackElement element;
        element.position = {std::uint8_t(id_), std::uint8_t(column), std::uint8_t(row)};
        element.type = type;
        element.rotation = rotation;
        element.article = article;
        element.text = text;
        element.deviceId = device;
        elements_.push_back(element);
        return *this;
    }
    // Straight track along a row, from one column to another (both included).
    DrawnPage& straight(int fromColumn, int toColumn, int row) {
        for (int column = fromColumn; column <= toColumn; ++column)
            tile(column, row, "gerade");
        return *this;
    }
    DrawnPage& contact(int column, int row, std::int64_t number, const std::string& label = {},
                       int rotation = 0) {
        return tile(column, row, "s88kontakt", rotation, number, label);
    }
    // A turnout or signal switched by keyboard number `keyboard` (`.artikel` = 2 x keyboard).
    DrawnPage& accessory(int column, int row, const std::string& type, int rotation, std::int64_t keyboard,
                         const std::string& label = {}) {
        return tile(column, row, type, rotation, 2 * keyboard, label);
    }
    // A buffer stop closing track that comes from the east (`west`) or from the west.
    DrawnPage& bufferStop(int column, int row, bool west) {
        return tile(column, row, "prellbock", west ? 2 : 0);
    }
    DrawnPage& arrow(int column, int row, int rotation, std::int64_t page, const std::string& label = {}) {
        return tile(column, row, "pfeil", rotation, page, label);
    }

    SourcePage source() const { return {id_, name_, &elements_}; }

private:
    std::int64_t id_;
    std::string name_;
    std::vector<cs2config::TrackElement> elements_;
};

// The source points into the pages: keep them while the graph is derived.
inline GraphSource sourceOf(const std::vector<DrawnPage>&& pages) = delete;
inline GraphSource sourceOf(const std::vector<DrawnPage>& pages) {
    GraphSource source;
    for (const DrawnPage& page : pages)
        source.pages.push_back(page.source());
    return source;
}

// Derives the graph and checks its invariants on the way.
inline TrackGraph derived(const GraphSource& source) {
    TrackGraph graph = TrackGraph::derive(source);
    for (const std::string& broken : brokenInvariants(graph))
        ADD_FAILURE() << "invariant broken: " << broken;
    return graph;
}

inline TrackGraph derived(const std::vector<DrawnPage>& pages) {
    const GraphSource source = sourceOf(pages);
    return derived(source);
}

// A layout folder read as `stellwerk-cli layout graph` reads it, with its graph.
struct FolderGraph {
    cs2config::LayoutFolder::Content content;
    std::optional<cs2config::RouteFile> routes;
    TrackGraph graph;

    explicit FolderGraph(const std::filesystem::path& folder)
        : content(cs2config::LayoutFolder::open(folder)) {
        EXPECT_EQ(content.problem, "") << folder;
        const cs2config::ConfigFile file =
            cs2config::ConfigFile::load(content.configDirectory / "fahrstrassen.cs2");
        if (const cs2config::RouteFile* read = file.model<cs2config::RouteFile>())
            routes = *read;
        graph = derived(GraphSource::of(content.layout, content.accessories ? &*content.accessories : nullptr,
                                        routes ? &*routes : nullptr));
    }
};

inline const Block* blockWith(const TrackGraph& graph, std::int64_t contact, std::int64_t device = 0) {
    const std::optional<int> id = graph.blockWithContact({device, contact});
    return id ? &graph.block(*id) : nullptr;
}

inline std::vector<std::int64_t> contactNumbers(const Block& block) {
    std::vector<std::int64_t> numbers;
    for (const ContactOnBlock& contact : block.contacts)
        numbers.push_back(contact.contact.number);
    return numbers;
}

inline TilePlace placeOf(const TrackGraph& graph, TileId tile) {
    return graph.tile(tile).place;
}

// The connections from a block end as "block end via turnouts" texts, e.g. "2a 5:straight".
inline std::vector<std::string> waysFrom(const TrackGraph& graph, const BlockEnd& end) {
    std::vector<std::string> ways;
    for (const int id : graph.connectionsFrom(end)) {
        const Connection& connection = graph.connection(id);
        std::string way = std::to_string(connection.to.block) + std::string(endName(connection.to.end));
        for (const TurnoutOnWay& turnout : connection.turnouts)
            way += " " + (turnout.article ? std::to_string(*turnout.article) : std::string("?")) + ":" +
                   std::string(positionName(turnout.kind, turnout.position));
        ways.push_back(way);
    }
    return ways;
}

inline std::vector<ProblemKind> problemKinds(const TrackGraph& graph) {
    std::vector<ProblemKind> kinds;
    for (const Problem& problem : graph.problems())
        kinds.push_back(problem.kind);
    return kinds;
}

inline std::size_t countProblems(const TrackGraph& graph, ProblemKind kind) {
    std::size_t n = 0;
    for (const Problem& problem : graph.problems())
        n += problem.kind == kind ? 1 : 0;
    return n;
}

} // namespace stellwerk::trackgraph::test

namespace stellwerk::trackgraph {
// Readable places in test failures.
inline void PrintTo(const TilePlace& place, std::ostream* out) {
    *out << "page " << place.page << " column " << place.column << " row " << place.row;
}
inline void PrintTo(const BlockEnd& end, std::ostream* out) {
    *out << "block " << end.block << " end " << endName(end.end);
}
} // namespace stellwerk::trackgraph
