#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/Diagnostics.h"
#include "cs2config/LocomotiveFile.h"
#include "cs2config/RouteFile.h"
#include "cs2config/TrackLayout.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::sim {

// The configuration a simulated station serves: the files by config-data key ("loks", "mags",
// "fs", "gbs", "gbs-<n>") and by HTTP path ("lokomotive.cs2", "gleisbilder/<name>.cs2"), and their
// typed models for the station's behaviour. Built from bytes in memory, so that a folder, the
// embedded demo and a test's inline files all take the same way.
class StationLayout {
public:
    using Files = std::map<std::string, std::string, std::less<>>;

    static constexpr std::string_view locomotivesPath = "lokomotive.cs2";
    static constexpr std::string_view accessoriesPath = "magnetartikel.cs2";
    static constexpr std::string_view routesPath = "fahrstrassen.cs2";
    static constexpr std::string_view trackPlanPath = "gleisbild.cs2";
    // Where the demo layout is embedded (resources/demo-layout/config/ as a Qt resource).
    static constexpr std::string_view demoResource = ":/demo-layout/config/";
    // Where the demo's locomotive pictures are embedded (resources/demo-layout/icons/).
    static constexpr std::string_view demoPictures = ":/demo-layout/icons/";

    StationLayout();

    // The files by path below /config/ ("lokomotive.cs2", "gleisbilder/Bahnhof.cs2"). Missing files
    // give empty models; every problem is in diagnostics().
    static StationLayout fromFiles(Files files);
    // Reads a CS2 config folder (lokomotive.cs2, magnetartikel.cs2, fahrstrassen.cs2, gleisbild.cs2,
    // gleisbilder/) into memory, and the pictures in the icons folder beside it (../icons/*.png).
    // Problems go to `diagnostics` as well as to diagnostics().
    static StationLayout load(const std::filesystem::path& configDirectory,
                              cs2config::Diagnostics& diagnostics);
    // The demo layout that ships with Stellwerk. When the resource is not built in, the layout is
    // empty and diagnostics() says so.
    static StationLayout demo();

    // The bytes of a file by its config-data key, or nullopt for a key the station does not serve.
    std::optional<std::string> fileForKey(std::string_view key) const;
    // The bytes of a file by its path below /config/ ("lokomotive.cs2", "gleisbilder/Bahnhof.cs2").
    std::optional<std::string> fileForPath(std::string_view path) const;
    // The path a key stands for ("loks" -> "lokomotive.cs2", "gbs-1" -> "gleisbilder/<page 1>.cs2").
    std::optional<std::string> pathForKey(std::string_view key) const;
    const Files& files() const { return files_; }
    // The locomotive pictures by file name ("BR 218.png"), served below /icons/.
    void setPictures(Files pictures) { pictures_ = std::move(pictures); }
    const Files& pictures() const { return pictures_; }
    std::optional<std::string> pictureFor(std::string_view fileName) const;

    const cs2config::LocomotiveFile& locomotives() const { return locomotives_; }
    const cs2config::AccessoryFile& accessories() const { return accessories_; }
    const cs2config::RouteFile& routes() const { return routes_; }
    const cs2config::TrackLayout& trackPlan() const { return trackPlan_; }
    // The page with this number, or null.
    const cs2config::TrackLayoutPage* page(std::int64_t id) const;
    // Everything reading the files found (file names included in each line).
    const std::vector<std::string>& diagnostics() const { return diagnostics_; }

private:
    void readModels();
    void readTrackPlan();
    void note(const cs2config::Diagnostics& diagnostics);

    Files files_;
    Files pictures_;
    cs2config::LocomotiveFile locomotives_;
    cs2config::AccessoryFile accessories_;
    cs2config::RouteFile routes_;
    cs2config::TrackLayout trackPlan_;
    std::vector<std::string> diagnostics_;
};

} // namespace stellwerk::sim
