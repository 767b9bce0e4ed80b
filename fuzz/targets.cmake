# What the fuzz targets are and which sources of Stellwerk they exercise; shared by the libFuzzer build
# (fuzz/CMakeLists.txt) and the replay tests of the main build (fuzz/replay.cmake).
set(STELLWERK_FUZZ_TARGETS
    frame_decode    # 13 network bytes -> CanFrame -> decode, encode, describe, build
    network_stream  # a TCP byte stream cut into segments -> FrameAssembler
    frame_text      # one line in any frame notation -> parseFrame, format, `decode --json`
    cli_arguments   # `encode NAME key=value...` and the locomotive/accessory/... words of the CLI
    cs2_document    # a .cs2 file -> Document and the typed reader its name selects -> write, json
    config_stream   # config-data stream frames -> ConfigStreamReceiver (CRC, inflate, limits)
    status_data     # status-data configuration packets -> device, reading and config channels
    loco_picture    # a loco's .icon value -> picture file name; picture bytes -> PNG header check
    mcan_frame      # 13-byte M-CAN frames in bus order -> decode (every role), encode, FrameReport, HandleRoles
    ro_frame        # RO module payloads (requests and answers, 11/29-bit) -> decode, encode, FrameReport, describe
    orc_frame       # 13-byte OpenRailCAN frames -> decode, encode, FrameReport, the bus description
    track_graph     # track plan pages (and accessories, routes) as .cs2 text -> TrackGraph, its invariants
    z21_datagram    # a Z21 client's (or server's) UDP datagram -> packets, requests (replies), written back
    withrottle_lines # a WiThrottle TCP stream -> lines (cut anywhere), client messages and server lines
)

file(GLOB STELLWERK_FUZZED_SOURCES CONFIGURE_DEPENDS
    ${STELLWERK_ROOT}/core/can/*.cpp
    ${STELLWERK_ROOT}/core/busreading/*.cpp
    ${STELLWERK_ROOT}/core/cs2/*.cpp
    ${STELLWERK_ROOT}/core/mcan/*.cpp
    ${STELLWERK_ROOT}/core/ro/*.cpp
    ${STELLWERK_ROOT}/core/orc/*.cpp
    ${STELLWERK_ROOT}/core/cs2config/*.cpp
    ${STELLWERK_ROOT}/core/trackgraph/*.cpp
    ${STELLWERK_ROOT}/core/z21/*.cpp
    ${STELLWERK_ROOT}/core/withrottle/*.cpp)
list(APPEND STELLWERK_FUZZED_SOURCES
    ${STELLWERK_ROOT}/core/transport/FrameAssembler.cpp
    ${STELLWERK_ROOT}/core/transport/NetworkFraming.cpp
    ${STELLWERK_ROOT}/core/station/DeviceDescription.cpp
    ${STELLWERK_ROOT}/core/station/StatusDataPackets.cpp
    ${STELLWERK_ROOT}/app/cli/CliNumber.cpp
    ${STELLWERK_ROOT}/app/cli/DecodeCommand.cpp
    ${STELLWERK_ROOT}/app/cli/LocArgument.cpp
    ${STELLWERK_ROOT}/app/cli/RoCli.cpp)
set(STELLWERK_FUZZED_INCLUDES ${STELLWERK_ROOT}/core ${STELLWERK_ROOT}/app/cli ${CMAKE_CURRENT_LIST_DIR})
