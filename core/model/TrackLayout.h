#pragma once

#include "cs2config/TrackElementType.h"
#include "cs2config/TrackPosition.h"
#include "model/FeedbackContact.h"
#include "station/StartupSequence.h"

#include <QString>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace stellwerk::model {

// One tile of a track plan page with what it is linked to (an accessory, a contact, a route, a page).
struct LayoutTile {
    cs2config::TrackPosition position;
    QString type; // the `.typ` word, for the renderer's icon
    cs2config::TrackCategory category = cs2config::TrackCategory::Empty;
    int rotation = 0;
    QString text;
    std::optional<std::int64_t> accessory; // keyboard id (field notes: `.artikel` = 2 x id, +1 second output)
    std::optional<ContactKey> contact;
    std::optional<std::int64_t> route;
    std::optional<std::int64_t> page;
};

// One page of the track plan, as the track plan view draws it.
struct LayoutPage {
    std::int64_t id = 0;
    QString name;
    int columns = 0;
    int rows = 0;
    std::vector<LayoutTile> tiles;
};

// Which tile of which page: what a change signal names.
struct TileRef {
    int page = 0; // index into TrackLayout::pages()
    int tile = 0;

    friend bool operator==(const TileRef&, const TileRef&) = default;
};

// The pages of the track plan with lookups from an accessory or contact to the tiles that show it, so
// that a changed position repaints exactly those tiles.
class TrackLayout {
public:
    TrackLayout() = default;
    explicit TrackLayout(const std::vector<station::DownloadedPage>& pages);

    const std::vector<LayoutPage>& pages() const { return pages_; }
    const LayoutTile& tile(TileRef ref) const {
        return pages_[std::size_t(ref.page)].tiles[std::size_t(ref.tile)];
    }
    const std::vector<TileRef>& tilesOfAccessory(std::int64_t id) const;
    const std::vector<TileRef>& tilesOfContact(ContactKey key) const;
    // Every contact a tile shows, with the tile's text as its name.
    std::vector<FeedbackContact> contacts() const;

private:
    static LayoutTile tileOf(const cs2config::TrackElement& element);
    void index(int page);

    std::vector<LayoutPage> pages_;
    std::unordered_map<std::int64_t, std::vector<TileRef>> byAccessory_;
    std::unordered_map<ContactKey, std::vector<TileRef>> byContact_;
};

} // namespace stellwerk::model
