#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/TrackElement.h"

#include <string_view>

namespace stellwerk::cs2config {

// What kind of tile draws an article of magnetartikel.cs2 (a turnout, a signal, ...): Output for the
// generic decoder outputs (std_*, k84_*), which drive any tile; Unknown for types we do not know.
TrackCategory tileCategoryOfArticle(std::string_view accessoryType);

// The article of magnetartikel.cs2 an accessory tile switches: `.artikel` = 2 x `.id` (+1 for the
// second output, the `.ungerade=1` half of a pair sharing the id), or the article whose further
// addresses cover that id (a three-way turnout's second address). Null when there is none.
const Accessory* articleOfTile(const TrackElement& element, const AccessoryFile& accessories);

// Why a tile cannot draw the article (a signal tile on a turnout, a left turnout on a right one);
// empty when it fits or either type is unknown.
std::string tileArticleMismatch(const TrackElement& element, const Accessory& article);

} // namespace stellwerk::cs2config
