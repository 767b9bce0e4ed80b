# locomotives sources of stellwerk-cs2config
# lokomotive.cs2, the loco status file lokomotive.sr2 and the MS2 loco streams (lokinfo, loknamen,
# lokliste, ldbver).
target_sources(stellwerk-cs2config PRIVATE
    cs2config/Locomotive.cpp
    cs2config/LocomotiveFieldWriter.cpp
    cs2config/LocomotiveEditor.cpp
    cs2config/LocomotiveFile.cpp
    cs2config/LocomotiveJson.cpp
    cs2config/LocomotivePicture.cpp
    cs2config/LocomotiveRecord.cpp
    cs2config/LocomotiveSections.cpp
    cs2config/LocomotiveStateFile.cpp
    cs2config/LocomotiveValues.cpp
    cs2config/Ms2LocoDatabaseVersion.cpp
    cs2config/Ms2LocoInfo.cpp
    cs2config/Ms2LocoNames.cpp
)
