#include "transport/DurationText.h"

namespace stellwerk::transport {

QString durationText(std::chrono::milliseconds duration) {
    const auto ms = duration.count();
    if (ms < 1000)
        return QStringLiteral("%1 ms").arg(ms);
    if (ms % 1000 == 0)
        return QStringLiteral("%1 s").arg(ms / 1000);
    return QStringLiteral("%1 s").arg(double(ms) / 1000.0, 0, 'f', ms % 100 == 0 ? 1 : 2);
}

} // namespace stellwerk::transport
