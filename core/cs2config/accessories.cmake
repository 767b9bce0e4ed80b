# accessories sources of stellwerk-cs2config: magnetartikel.cs2 (and the MS2's maginfo stream),
# magnetartikel.sr2 and fahrstrassen.cs2 as typed models.
target_sources(stellwerk-cs2config PRIVATE
    cs2config/AccessoryAddressCheck.cpp
    cs2config/AccessoryFile.cpp
    cs2config/AccessoryRecordSupport.cpp
    cs2config/AccessoryStatusFile.cpp
    cs2config/AccessoryType.cpp
    cs2config/RouteAccessoryCheck.cpp
    cs2config/RouteDelay.cpp
    cs2config/RouteFile.cpp
)
