// The track graph of any pages: the input is .cs2 text cut at its section headers, each [gleisbildseite]
// a page (numbered 0, 1, ... and named "Seite0", "Seite1", ... so that arrows can name them either way),
// a [magnetartikel] section the accessories and a [fahrstrassen] section the routes.
// Invariants (trackgraph::brokenInvariants): every contact in at most one block; ids count from 1; every
// connection joins two existing block ends with positions that set its legs, and conflicts both ways;
// every block runs from end a to end b over joined track. Besides: deriving twice, or from the pages listed
// in the opposite order, gives the same graph; the JSON is valid; following the track from any block end
// ends at a block that exists.
#include "FuzzSupport.h"
#include "cs2config/AccessoryFile.h"
#include "cs2config/Document.h"
#include "cs2config/RouteFile.h"
#include "cs2config/TrackPage.h"
#include "trackgraph/GraphInvariants.h"
#include "trackgraph/GraphReport.h"
#include "trackgraph/TrackGraph.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

using namespace stellwerk;

namespace {

struct Files {
    std::vector<cs2config::TrackPage> pages;
    std::optional<cs2config::AccessoryFile> accessories;
    std::optional<cs2config::RouteFile> routes;
};

// The sections of the text: each starts at a line beginning with '['.
std::vector<std::string_view> sections(std::string_view text) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t line = 0; line < text.size();) {
        if (text[line] == '[' && line > start) {
            parts.push_back(text.substr(start, line - start));
            start = line;
        }
        const std::size_t end = text.find('\n', line);
        if (end == std::string_view::npos)
            break;
        line = end + 1;
    }
    parts.push_back(text.substr(start));
    return parts;
}

Files read(std::string_view text) {
    Files files;
    for (const std::string_view part : sections(text)) {
        cs2config::Diagnostics diagnostics;
        const cs2config::Document document = cs2config::Document::parse(part, diagnostics);
        if (part.starts_with("[magnetartikel]"))
            files.accessories = cs2config::AccessoryFile::read(document, diagnostics);
        else if (part.starts_with("[fahrstrassen]"))
            files.routes = cs2config::RouteFile::read(document, diagnostics);
        else if (part.starts_with("[gleisbildseite]") && files.pages.size() < 8)
            files.pages.push_back(cs2config::TrackPage::read(document, diagnostics));
    }
    return files;
}

trackgraph::GraphSource sourceOf(const Files& files, bool reversed) {
    trackgraph::GraphSource source;
    for (std::size_t i = 0; i < files.pages.size(); ++i) {
        const std::size_t page = reversed ? files.pages.size() - 1 - i : i;
        source.pages.push_back(
            {std::int64_t(page), "Seite" + std::to_string(page), &files.pages[page].elements});
    }
    source.accessories = files.accessories ? &*files.accessories : nullptr;
    source.routes = files.routes ? &*files.routes : nullptr;
    return source;
}

// Following the track from every block end (turnouts all diverging, then all straight) ends somewhere that
// exists, after a joined path.
void checkFollowing(const trackgraph::TrackGraph& graph) {
    for (const int position : {0, 1})
        for (const trackgraph::Block& block : graph.blocks())
            for (const trackgraph::End end : {trackgraph::End::A, trackgraph::End::B}) {
                const trackgraph::Lead lead = graph.follow(
                    {block.id, end}, [position](std::int64_t) { return std::optional(position); });
                const bool reached =
                    lead.kind != trackgraph::LeadKind::Block ||
                    (lead.reached.block >= 1 && lead.reached.block <= int(graph.blocks().size()));
                fuzz::check(reached, "following the track reaches a block that does not exist");
                for (const trackgraph::TrackStep& step : lead.path)
                    fuzz::check(step.tile < graph.tiles().size(),
                                "following the track passes a tile that does not exist");
            }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024)
        return -1;
    const Files files = read({reinterpret_cast<const char*>(data), size});
    const trackgraph::TrackGraph graph = trackgraph::TrackGraph::derive(sourceOf(files, false));
    std::string broken;
    for (const std::string& rule : trackgraph::brokenInvariants(graph))
        broken += rule + "\n";
    fuzz::check(broken.empty(), "a track graph invariant is broken", broken);
    checkFollowing(graph);
    const std::string json = trackgraph::toJson(graph);
    fuzz::check(fuzz::isJsonDocument(json, true), "the track graph's JSON is not valid", json);
    fuzz::check(trackgraph::toJson(trackgraph::TrackGraph::derive(sourceOf(files, false))) == json,
                "deriving the same pages twice gives another graph");
    fuzz::check(trackgraph::toJson(trackgraph::TrackGraph::derive(sourceOf(files, true))) == json,
                "the order of the pages changes the graph");
    return 0;
}
