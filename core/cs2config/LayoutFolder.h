#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/LayoutCheck.h"
#include "cs2config/TrackLayout.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// The files of a CS2 configuration folder by their path inside `config/` ("gleisbild.cs2",
// "gleisbilder/Bahnhof.cs2", "magnetartikel.cs2"), with their bytes.
using ConfigFolderFiles = std::map<std::string, std::string>;

// A CS2 configuration folder on disk, as a CS2 keeps it and serves it over HTTP: config/gleisbild.cs2,
// config/gleisbilder/<page>.cs2 and the station's other files. Opened to look at a layout without a
// station; written to hand a layout back to a CS2. Writing never leaves a half-written folder.
class LayoutFolder {
public:
    // How much of a layout there was to open.
    enum class Extent {
        Folder,     // gleisbild.cs2 and the pages it lists
        PagesOnly,  // gleisbild.cs2 is missing: the page files found in gleisbilder/ (TrackLayout::loadPages)
        SinglePage, // one page file was opened alone
    };

    // What opening a folder found. `layout` is usable when `problem` is empty.
    struct Content {
        std::filesystem::path configDirectory;
        Extent extent = Extent::Folder;
        TrackLayout layout;
        std::optional<AccessoryFile> accessories; // magnetartikel.cs2, for the articles' names
        std::string problem;                      // why nothing could be opened; empty on success
        std::vector<LayoutFinding> findings;      // what LayoutCheck found in the files together
    };

    // The `config` folder inside `folder`, or `folder` itself when it holds gleisbild.cs2 (or, without
    // one anywhere, a gleisbilder/ folder of pages); the folder above when `folder` is a gleisbilder/.
    static std::filesystem::path configDirectoryOf(const std::filesystem::path& folder);
    // Reads the layout of a configuration folder, as far as it is there: the folder with its index, or
    // the pages of its gleisbilder/ when the index is missing. `path` may also be a single page file
    // (gleisbilder/<page>.cs2), shown alone, or a gleisbild.cs2, which opens its folder.
    static Content open(const std::filesystem::path& path);
    // Where the locomotive pictures of a layout are: the icons folder beside its config folder.
    static std::filesystem::path iconsDirectoryOf(const std::filesystem::path& configDirectory);

    // The files in `configDirectory` that a CS2 keeps and that were read: gleisbild.cs2, the page files
    // of `layout` and the companion files, each by its path inside the folder ("gleisbilder/x.cs2").
    static std::vector<std::string> presentFiles(const Content& content);

    // The files of a layout as a CS2 stores them, written with the models' writers (unchanged models
    // give their files back byte for byte).
    static ConfigFolderFiles filesOf(const TrackPlan& plan, const std::vector<TrackLayoutPage>& pages);
    // The station's other downloaded files (stream key -> contents: "loks", "mags", "fs") under their
    // file names; track plan keys and keys without a file name are left out.
    static ConfigFolderFiles stationFiles(const std::map<std::string, std::string>& files);
    // The files of `configDirectory` other than the track plan that a CS2 reads (magnetartikel.cs2,
    // lokomotive.cs2, fahrstrassen.cs2), so that an export of an opened folder keeps them.
    static ConfigFolderFiles companionFiles(const std::filesystem::path& configDirectory);

    // Writes `files` into `folder`/config: first into a new folder beside it, then swapped into place,
    // so that a failure leaves the old folder as it was. Returns an empty string or the reason it failed.
    static std::string write(const std::filesystem::path& folder, const ConfigFolderFiles& files);

private:
    static Content openPageFile(const std::filesystem::path& file);
    static void checkAgainstAccessories(Content& content);
};

} // namespace stellwerk::cs2config
