# layout sources of stellwerk-cs2config: the track plan (gleisbild.cs2, its pages, gleisbild.sr2)
target_sources(stellwerk-cs2config PRIVATE
    cs2config/LayoutCheck.cpp
    cs2config/LayoutFolder.cpp
    cs2config/TileArticle.cpp
    cs2config/TrackElement.cpp
    cs2config/TrackElementType.cpp
    cs2config/TrackFields.cpp
    cs2config/TrackFile.cpp
    cs2config/TrackLayout.cpp
    cs2config/TrackPage.cpp
    cs2config/TrackPlan.cpp
    cs2config/TrackPosition.cpp
    cs2config/TrackStatus.cpp
)
