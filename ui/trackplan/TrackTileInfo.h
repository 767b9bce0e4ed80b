#pragma once

#include "cs2config/TrackElementType.h"

#include <QCoreApplication>
#include <QString>

namespace stellwerk::model {
struct LayoutTile;
}

namespace stellwerk::ui {

// The words a person reads about a tile: what it is, what its positions are called, its tooltip.
class TrackTileInfo {
    Q_DECLARE_TR_FUNCTIONS(TrackTileInfo)

public:
    // "Left turnout", "Signal", "S88 contact", ... for a `.typ` word.
    static QString typeName(const QString& type, cs2config::TrackCategory category);
    // "Straight", "Stop (Hp0)", ... for a position of an accessory shown by this type.
    static QString positionName(const QString& type, cs2config::TrackCategory category, int position);
    // Type, address and name (or text), one per line.
    static QString toolTip(const model::LayoutTile& tile, const QString& name);
};

} // namespace stellwerk::ui
