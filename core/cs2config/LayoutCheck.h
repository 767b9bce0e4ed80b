#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/TrackLayout.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// One problem of a layout folder as a whole: which file and line, and a sentence a person can act on.
struct LayoutFinding {
    std::string file; // "gleisbild.cs2", "gleisbilder/karben.cs2"
    int line = 0;     // 1-based; 0 = the file as a whole
    std::string message;

    // "gleisbilder/karben.cs2:27: warning: ...", the file inside `directory` when one is given.
    std::string format(const std::filesystem::path& directory = {}) const;
};

// Checks the files of a layout folder against each other, which no single file's reader can: pages
// that gleisbild.cs2 lists without their file, two tiles switching one article, and tiles whose type
// or label disagrees with the article of magnetartikel.cs2 they switch. Every tile is reported at most
// once for its type or label, every shared article once, and a page that mostly does not fit
// magnetartikel.cs2 once, so that a hand-made page or a wrong file does not drown the real problems.
class LayoutCheck {
public:
    // `accessories` may be null (a folder without magnetartikel.cs2): then tiles are not compared.
    LayoutCheck(const TrackLayout& layout, const AccessoryFile* accessories);

    std::vector<LayoutFinding> run();

private:
    struct PlacedTile {
        const TrackLayoutPage* page;
        const TrackElement* element;
    };

    void checkMissingPages();
    void checkSharedArticles(const std::vector<PlacedTile>& tiles);
    void checkPageByPage(const std::vector<PlacedTile>& tiles);
    void checkPageTiles(const std::vector<PlacedTile>& tiles);
    std::optional<std::string> checkTile(const PlacedTile& tile);
    void checkLabel(const PlacedTile& tile, const Accessory& article);
    std::vector<PlacedTile> accessoryTiles() const;
    void report(const PlacedTile& tile, std::string message);

    const TrackLayout& layout_;
    const AccessoryFile* accessories_;
    std::vector<LayoutFinding> findings_;
};

} // namespace stellwerk::cs2config
