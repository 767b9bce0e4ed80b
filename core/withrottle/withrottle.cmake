# The WiThrottle codec (core/withrottle): the lines of Engine Driver and WiThrottle and every line a
# WiThrottle server sends, and the line splitter of the TCP stream. Pure C++, no Qt.
stellwerk_core_library(withrottle PURE)
target_sources(stellwerk-withrottle PRIVATE
    withrottle/ClientCodec.cpp
    withrottle/ClientFormat.cpp
    withrottle/ClientMessages.h
    withrottle/LineSplitter.cpp
    withrottle/LineSplitter.h
    withrottle/ServerFormat.cpp
    withrottle/ServerLines.h
    withrottle/ServerParse.cpp
    withrottle/Text.cpp
    withrottle/Text.h
)
