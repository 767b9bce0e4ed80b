#include "cs2config/TileArticle.h"

#include <string>

namespace stellwerk::cs2config {

namespace {

bool contains(std::string_view text, std::string_view part) {
    return text.find(part) != std::string_view::npos;
}

std::string_view categoryWords(TrackCategory category) {
    switch (category) {
    case TrackCategory::Turnout:
        return "a turnout";
    case TrackCategory::Signal:
        return "a signal";
    case TrackCategory::Uncoupler:
        return "an uncoupler";
    case TrackCategory::Output:
        return "an output";
    case TrackCategory::Turntable:
        return "a turntable";
    case TrackCategory::TransferTable:
        return "a transfer table";
    default:
        return "another kind of article";
    }
}

// rechtsweiche and linksweiche are mirror images: the tile would draw the turnout the wrong way.
bool mirroredTurnout(std::string_view tileType, std::string_view articleType) {
    return (tileType == "linksweiche" && articleType == "rechtsweiche") ||
           (tileType == "rechtsweiche" && articleType == "linksweiche");
}

} // namespace

TrackCategory tileCategoryOfArticle(std::string_view type) {
    if (type.starts_with("std_") || type.starts_with("k84_"))
        return TrackCategory::Output;
    if (contains(type, "signal"))
        return TrackCategory::Signal;
    if (contains(type, "weiche") || type.starts_with("DKW"))
        return TrackCategory::Turnout;
    if (type.starts_with("entkupplungsgleis"))
        return TrackCategory::Uncoupler;
    if (contains(type, "drehscheibe"))
        return TrackCategory::Turntable;
    if (type.starts_with("schiebebuehne"))
        return TrackCategory::TransferTable;
    return TrackCategory::Unknown;
}

const Accessory* articleOfTile(const TrackElement& element, const AccessoryFile& accessories) {
    const std::optional<std::int64_t> id = element.accessoryId();
    if (!id)
        return nullptr;
    const Accessory* found = nullptr;
    for (const Accessory& article : accessories.accessories)
        if (article.id == *id && (!found || article.secondOutput == element.onSecondOutput()))
            found = &article;
    if (found)
        return found;
    for (const Accessory& article : accessories.accessories)
        if (*id > article.id && *id < article.id + article.addressCount())
            return &article;
    return nullptr;
}

std::string tileArticleMismatch(const TrackElement& element, const Accessory& article) {
    const TrackCategory tile = element.category();
    const TrackCategory drawn = tileCategoryOfArticle(article.type);
    if (tile == TrackCategory::Unknown || drawn == TrackCategory::Unknown || drawn == TrackCategory::Output)
        return {};
    if (tile != drawn)
        return std::string(categoryWords(tile)) + " tile linked to " + std::string(categoryWords(drawn));
    if (mirroredTurnout(element.type, article.type))
        return "a " + element.type + " tile linked to a " + article.type;
    return {};
}

} // namespace stellwerk::cs2config
