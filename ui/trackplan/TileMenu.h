#pragma once

#include <QCoreApplication>

class QMenu;

namespace stellwerk::model {
class Railway;
struct LayoutTile;
} // namespace stellwerk::model

namespace stellwerk::ui {

// What a right click on a tile offers: the positions of its accessory, for an occupied contact which
// locomotive is on it (the user says what a real station cannot, and the plan names the train there), or for
// a route button running the route from Stellwerk or asking the station to run it from its memory.
class TileMenu final {
    Q_DECLARE_TR_FUNCTIONS(TileMenu)

public:
    // Fills `menu` for the tile on a railway whose state is reported; false when there is nothing to offer.
    static bool fill(QMenu& menu, const model::LayoutTile& tile, model::Railway& railway);

private:
    static bool fillPositions(QMenu& menu, const model::LayoutTile& tile, model::Railway& railway);
    static bool fillRoute(QMenu& menu, const model::LayoutTile& tile, model::Railway& railway);
    static bool fillOccupants(QMenu& menu, const model::LayoutTile& tile, model::Railway& railway);
};

} // namespace stellwerk::ui
