#include "cs2config/ConfigStreamError.h"

namespace stellwerk::cs2config {

std::string_view streamErrorKindName(StreamErrorKind kind) {
    switch (kind) {
    case StreamErrorKind::CrcMismatch:
        return "crc-mismatch";
    case StreamErrorKind::SizeMismatch:
        return "size-mismatch";
    case StreamErrorKind::MoreDataThanAnnounced:
        return "more-data-than-announced";
    case StreamErrorKind::InflateFailed:
        return "inflate-failed";
    case StreamErrorKind::TooLarge:
        return "too-large";
    case StreamErrorKind::DataWithoutHeader:
        return "data-without-header";
    case StreamErrorKind::Interrupted:
        return "interrupted";
    case StreamErrorKind::Incomplete:
        return "incomplete";
    }
    return "unknown";
}

} // namespace stellwerk::cs2config
