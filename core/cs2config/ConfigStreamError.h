#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace stellwerk::cs2config {

// The ways a config-data stream (document 7.2) can arrive broken.
enum class StreamErrorKind : std::uint8_t {
    CrcMismatch,           // the CRC over the received bytes differs from the header's
    SizeMismatch,          // the inflated file is not as long as its 4-byte prefix announces
    MoreDataThanAnnounced, // a data frame after the announced length was complete
    InflateFailed,         // the zlib stream is damaged or cut short
    TooLarge,              // the stream or the file it announces is above the receiver's limit
    DataWithoutHeader,     // a data frame with no header (DLC 6 or 7) before it
    Interrupted,           // a new header or a frame of another length arrived inside the stream
    Incomplete,            // the input ended before the announced length arrived
};

std::string_view streamErrorKindName(StreamErrorKind kind);

// Why a stream was rejected; `message` says what, for which file and hash, and what was dropped.
struct ConfigStreamError {
    StreamErrorKind kind;
    std::string message;
};

} // namespace stellwerk::cs2config
