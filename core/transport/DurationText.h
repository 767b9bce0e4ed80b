#pragma once

#include <QString>
#include <chrono>

namespace stellwerk::transport {

// A wait as a person reads it in a message: "4 s", "1.5 s", "250 ms" (not "4000 ms").
QString durationText(std::chrono::milliseconds duration);

} // namespace stellwerk::transport
