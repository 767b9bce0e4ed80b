#include "automation/LayoutGraph.h"

#include "cs2config/ConfigFile.h"
#include "cs2config/LayoutFolder.h"
#include "station/StartupSequence.h"

#include <algorithm>
#include <optional>

namespace stellwerk::automation {

trackgraph::TrackGraph graphOf(const station::StartupResult& startup) {
    trackgraph::GraphSource source;
    for (const station::DownloadedPage& page : startup.pages)
        source.pages.push_back({page.id, page.name, &page.page.elements});
    source.accessories = startup.accessories ? &*startup.accessories : nullptr;
    source.routes = startup.routes ? &*startup.routes : nullptr;
    return trackgraph::TrackGraph::derive(source);
}

Expected<trackgraph::TrackGraph, std::string> graphOfFolder(const std::filesystem::path& folder) {
    const cs2config::LayoutFolder::Content content = cs2config::LayoutFolder::open(folder);
    if (!content.problem.empty())
        return content.problem;
    if (std::none_of(content.layout.pages.begin(), content.layout.pages.end(),
                     [](const cs2config::TrackLayoutPage& page) { return page.loaded; }))
        return "no page of the track plan in " + content.configDirectory.string() + " could be read";
    std::optional<cs2config::RouteFile> routes;
    std::error_code error;
    if (const auto file = content.configDirectory / "fahrstrassen.cs2";
        std::filesystem::is_regular_file(file, error))
        if (const cs2config::ConfigFile config = cs2config::ConfigFile::load(file);
            const auto* loaded = config.model<cs2config::RouteFile>())
            routes = *loaded;
    return trackgraph::TrackGraph::derive(
        content.layout, content.accessories ? &*content.accessories : nullptr, routes ? &*routes : nullptr);
}

} // namespace stellwerk::automation
