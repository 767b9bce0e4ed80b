# The .cs2 text format: lines kept as read, nested by their dots.
target_sources(stellwerk-cs2config PRIVATE
    cs2config/ConfigFile.cpp
    cs2config/ConfigKind.cpp
    cs2config/Diagnostics.cpp
    cs2config/Document.cpp
    cs2config/DocumentParser.cpp
    cs2config/JsonWriter.cpp
    cs2config/LineClassifier.cpp
    cs2config/Node.cpp
    cs2config/RecordEditor.cpp
    cs2config/ReportOnce.cpp
    cs2config/Text.cpp
    cs2config/Values.cpp
)
