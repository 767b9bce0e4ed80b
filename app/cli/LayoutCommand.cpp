#include "LayoutCommand.h"

#include "cs2config/ConfigFile.h"
#include "cs2config/LayoutFolder.h"
#include "trackgraph/GraphReport.h"
#include "trackgraph/TrackGraph.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <ostream>

namespace stellwerk::cli {

namespace {

constexpr const char* Usage = "usage: stellwerk-cli layout graph DIR [--json]\n";

int usageError(std::ostream& err, const std::string& problem) {
    err << "stellwerk-cli layout: " << problem << "\n" << Usage;
    return 2;
}

// fahrstrassen.cs2 beside the track plan, when it is there and readable.
std::optional<cs2config::RouteFile> routesOf(const std::filesystem::path& configDirectory) {
    std::error_code error;
    const std::filesystem::path file = configDirectory / "fahrstrassen.cs2";
    if (!std::filesystem::is_regular_file(file, error))
        return std::nullopt;
    const cs2config::ConfigFile config = cs2config::ConfigFile::load(file);
    if (const cs2config::RouteFile* routes = config.model<cs2config::RouteFile>())
        return *routes;
    return std::nullopt;
}

bool anyPageRead(const cs2config::TrackLayout& layout) {
    return std::any_of(layout.pages.begin(), layout.pages.end(),
                       [](const cs2config::TrackLayoutPage& page) { return page.loaded; });
}

int runGraph(const std::string& folder, bool json, std::ostream& out, std::ostream& err) {
    const cs2config::LayoutFolder::Content content = cs2config::LayoutFolder::open(folder);
    if (!content.problem.empty()) {
        err << "stellwerk-cli layout graph: " << content.problem << "\n";
        return 1;
    }
    if (!anyPageRead(content.layout)) {
        err << "stellwerk-cli layout graph: no page of the track plan in " << content.configDirectory.string()
            << " could be read\n";
        return 1;
    }
    const std::optional<cs2config::RouteFile> routes = routesOf(content.configDirectory);
    const trackgraph::TrackGraph graph = trackgraph::TrackGraph::derive(
        content.layout, content.accessories ? &*content.accessories : nullptr, routes ? &*routes : nullptr);
    out << (json ? trackgraph::toJson(graph) : trackgraph::describeGraph(graph));
    return 0;
}

} // namespace

int runLayout(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    if (arguments.empty() || arguments[0] != "graph")
        return usageError(err,
                          arguments.empty() ? "missing command" : "unknown command '" + arguments[0] + "'");
    std::string folder;
    bool json = false;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        if (arguments[i] == "--json")
            json = true;
        else if (folder.empty() && !arguments[i].starts_with("-"))
            folder = arguments[i];
        else
            return usageError(err, "unexpected argument '" + arguments[i] + "'");
    }
    if (folder.empty())
        return usageError(err, "graph needs a layout folder DIR");
    return runGraph(folder, json, out, err);
}

} // namespace stellwerk::cli
