#include "model/TrackLayout.h"

namespace stellwerk::model {
namespace {

const std::vector<TileRef> NoTiles;

} // namespace

TrackLayout::TrackLayout(const std::vector<station::DownloadedPage>& pages) {
    for (const station::DownloadedPage& downloaded : pages) {
        LayoutPage page;
        page.id = downloaded.id;
        page.name = QString::fromStdString(downloaded.name);
        if (const auto area = downloaded.page.area()) {
            page.columns = area->columns();
            page.rows = area->rows();
        }
        for (const cs2config::TrackElement& element : downloaded.page.elements)
            page.tiles.push_back(tileOf(element));
        pages_.push_back(std::move(page));
        index(int(pages_.size()) - 1);
    }
}

LayoutTile TrackLayout::tileOf(const cs2config::TrackElement& element) {
    LayoutTile tile;
    tile.position = element.position;
    tile.type = QString::fromStdString(element.type);
    tile.category = element.category();
    tile.rotation = element.rotation;
    tile.text = QString::fromStdString(element.text);
    if (!element.hasArticle())
        return tile;
    switch (element.articleLink()) {
    case cs2config::ArticleLink::Accessory:
        tile.accessory = element.accessoryId();
        break;
    case cs2config::ArticleLink::FeedbackContact:
        tile.contact = contactKey(std::uint16_t(element.deviceId), std::uint16_t(element.article));
        break;
    case cs2config::ArticleLink::Route:
        tile.route = element.article;
        break;
    case cs2config::ArticleLink::Page:
        tile.page = element.article;
        break;
    case cs2config::ArticleLink::None:
        break;
    }
    return tile;
}

void TrackLayout::index(int page) {
    const auto& tiles = pages_[std::size_t(page)].tiles;
    for (int i = 0; i < int(tiles.size()); ++i) {
        if (tiles[std::size_t(i)].accessory)
            byAccessory_[*tiles[std::size_t(i)].accessory].push_back({page, i});
        if (tiles[std::size_t(i)].contact)
            byContact_[*tiles[std::size_t(i)].contact].push_back({page, i});
    }
}

const std::vector<TileRef>& TrackLayout::tilesOfAccessory(std::int64_t id) const {
    const auto it = byAccessory_.find(id);
    return it == byAccessory_.end() ? NoTiles : it->second;
}

const std::vector<TileRef>& TrackLayout::tilesOfContact(ContactKey key) const {
    const auto it = byContact_.find(key);
    return it == byContact_.end() ? NoTiles : it->second;
}

std::vector<FeedbackContact> TrackLayout::contacts() const {
    std::vector<FeedbackContact> result;
    for (const auto& [key, refs] : byContact_)
        result.emplace_back(std::uint16_t(key >> 16), std::uint16_t(key & 0xFFFF), tile(refs.front()).text);
    return result;
}

} // namespace stellwerk::model
