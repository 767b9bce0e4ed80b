#include "trackgraph/TrackTiles.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace stellwerk::trackgraph {

namespace {

Tile tileOf(const cs2config::TrackElement& element, std::int64_t pageId, std::uint32_t page) {
    Tile tile;
    tile.place = {pageId, element.position.column, element.position.row};
    tile.page = page;
    tile.type = element.type;
    tile.rotation = element.rotation & 3;
    tile.shape = rotatedShape(tileShapeOf(element.type), tile.rotation);
    tile.accessory = element.accessoryId();
    tile.article = element.article;
    tile.text = element.text;
    if (element.articleLink() == cs2config::ArticleLink::FeedbackContact && element.hasArticle())
        tile.contact = ContactKey{element.deviceId, element.article};
    else if (tile.shape.role == TileRole::Contact)
        tile.shape.role = TileRole::Track; // a contact tile without a number watches nothing
    return tile;
}

auto placeKey(const Tile& tile) {
    return std::tuple(tile.page, tile.place.row, tile.place.column);
}

} // namespace

TrackTiles TrackTiles::of(const std::vector<SourcePage>& pages) {
    // Pages by number; pages sharing a number keep the order of gleisbild.cs2.
    std::vector<std::uint32_t> order(pages.size());
    std::iota(order.begin(), order.end(), 0U);
    std::stable_sort(order.begin(), order.end(),
                     [&pages](std::uint32_t a, std::uint32_t b) { return pages[a].id < pages[b].id; });
    TrackTiles result;
    for (std::uint32_t index = 0; index < order.size(); ++index)
        result.addPage(index, pages[order[index]]);
    // Stable: of two tiles on one place, the one first in its file stays first and is kept.
    std::stable_sort(result.tiles_.begin(), result.tiles_.end(),
                     [](const Tile& a, const Tile& b) { return placeKey(a) < placeKey(b); });
    const auto samePlace = [](const Tile& a, const Tile& b) { return placeKey(a) == placeKey(b); };
    result.tiles_.erase(std::unique(result.tiles_.begin(), result.tiles_.end(), samePlace),
                        result.tiles_.end());
    result.tiles_.shrink_to_fit();
    return result;
}

void TrackTiles::addPage(std::uint32_t index, const SourcePage& source) {
    pages_.push_back({source.id, source.name, source.elements != nullptr});
    if (!source.elements)
        return;
    for (const cs2config::TrackElement& element : *source.elements)
        tiles_.push_back(tileOf(element, source.id, index));
}

std::optional<TileId> TrackTiles::at(std::uint32_t page, int column, int row) const {
    const auto key = std::tuple(page, row, column);
    const auto found = std::lower_bound(tiles_.begin(), tiles_.end(), key,
                                        [](const Tile& tile, const auto& k) { return placeKey(tile) < k; });
    if (found == tiles_.end() || placeKey(*found) != key)
        return std::nullopt;
    return TileId(found - tiles_.begin());
}

std::optional<TileId> TrackTiles::beside(TileId tile, Port port) const {
    if (!isGeometric(port))
        return std::nullopt;
    const Tile& from = tiles_[tile];
    const auto [dx, dy] = offsetOf(port);
    return at(from.page, from.place.column + dx, from.place.row + dy);
}

std::optional<TileId> TrackTiles::joinedAt(TileId tile, Port port) const {
    const std::optional<TileId> other = beside(tile, port);
    if (!other)
        return std::nullopt;
    for (const Leg& leg : tiles_[*other].shape.legs())
        if (leg.touches(facing(port)))
            return other;
    return std::nullopt;
}

std::optional<std::uint32_t> TrackTiles::pageWithId(std::int64_t id) const {
    for (std::uint32_t i = 0; i < pages_.size(); ++i)
        if (pages_[i].id == id)
            return i;
    return std::nullopt;
}

std::optional<std::uint32_t> TrackTiles::pageNamed(std::string_view name) const {
    for (std::uint32_t i = 0; i < pages_.size(); ++i)
        if (pages_[i].name == name)
            return i;
    return std::nullopt;
}

} // namespace stellwerk::trackgraph
