#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/Diagnostics.h"
#include "cs2config/RouteFile.h"

namespace stellwerk::cs2config {

// Checks fahrstrassen.cs2 against magnetartikel.cs2: every accessory step must switch an accessory the
// keyboard has, to a position its type has. Reports with the route file's line numbers; changes nothing.
void checkRouteAccessories(const RouteFile& routes, const AccessoryFile& accessories,
                           Diagnostics& diagnostics);

} // namespace stellwerk::cs2config
