#pragma once

// The waits the connection tests share: how long a start-up and a reconnect may take, and waiting for a
// condition or for the connection to be ready (one definition for the test program's unity build).

#include "connection/StationConnection.h"

#include <QTest>
#include <functional>

namespace stellwerk::connection::test {

// The start-up lists devices for half a second, then downloads and asks; generous for a loaded machine.
inline constexpr int ReadyMs = 10000;
// The transport's back-off is at most 5 s, plus an attempt.
inline constexpr int ReconnectMs = 12000;

inline bool waitUntil(const std::function<bool()>& done, int timeoutMs = ReadyMs) {
    return QTest::qWaitFor(done, timeoutMs);
}

inline bool ready(const StationConnection& connection) {
    return waitUntil([&] { return connection.state() == StationConnection::State::Ready; }, ReadyMs);
}

} // namespace stellwerk::connection::test
