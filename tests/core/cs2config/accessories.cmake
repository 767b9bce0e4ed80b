# accessories tests (tests/core/cs2config): magnetartikel.cs2, maginfo, magnetartikel.sr2, fahrstrassen.cs2.
target_sources(stellwerk-core-tests PRIVATE
    cs2config/AccessoryFileDiagnosticsTest.cpp
    cs2config/AccessoryFileTest.cpp
    cs2config/AccessoryStatusFileTest.cpp
    cs2config/AccessoryTypeTest.cpp
    cs2config/MaginfoTest.cpp
    cs2config/RouteFileTest.cpp
)
