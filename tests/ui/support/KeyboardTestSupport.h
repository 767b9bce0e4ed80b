#pragma once

// The demo layout's simulated CS2 on a free loopback port, with the station itself at hand so that the
// keyboard and settings tests can check what it did; and a connection with its railway bound to it.

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "model/Railway.h"
#include "support/StationTestSupport.h"

#include <QTest>
#include <memory>

namespace stellwerk::ui::test {

inline constexpr int CommandMs = 5000; // generous for a loaded machine

// The demo layout's simulated CS2 with the station at hand (TestStation offers it).
using DemoStation = TestStation;

// A controller on the station: a connection and the railway of its session.
class Controller {
public:
    bool connect(const QString& url) {
        connection.connectTo(url);
        return waitForState(connection, connection::StationConnection::State::Ready) && railways.railway();
    }
    model::Railway* railway() const { return railways.railway(); }

    connection::StationConnection connection{support::withEmbeddedStation()};
    binding::RailwayBinding railways{connection};
};

} // namespace stellwerk::ui::test
