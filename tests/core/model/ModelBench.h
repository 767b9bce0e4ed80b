#pragma once

// A simulated CS2 behind a loopback pair, a station session with its start-up on the other end, and the
// railway model on top: the way the app runs, with the simulator as a real peer behind a transport.

#include "model/Railway.h"
#include "sim/SimulatedStation.h"
#include "station/StartupSequence.h"
#include "station/StationSession.h"
#include "transport/LoopbackTransport.h"

#include <QSignalSpy>
#include <QTest>
#include <functional>
#include <gtest/gtest.h>

namespace stellwerk::model::test {

using namespace std::chrono_literals;

// Long enough for a loaded two-core machine; waits end as soon as the condition holds.
inline constexpr int WaitMs = 5000;

inline bool waitFor(const std::function<bool()>& condition, int timeoutMs = WaitMs) {
    return QTest::qWaitFor(condition, timeoutMs);
}

inline constexpr std::uint32_t Br86 = 0x4006; // mfx, F0 light, F1 sound
inline constexpr std::uint32_t V100 = 0xC003; // DCC 3
inline constexpr std::uint32_t CentralStationUid = 0x43533201;

inline const char* const Locomotives = R"([lokomotive]
version
 .minor=3
lokomotive
 .name=BR 86
 .uid=0x4006
 .adresse=0x6
 .typ=mfx
 .funktionen
 ..nr=0
 ..typ=1
 .funktionen
 ..nr=1
 ..typ=23
 ..dauer=-1
lokomotive
 .name=V 100
 .uid=0xc003
 .adresse=0x3
 .typ=dcc
)";

// Turnout 1, three-way turnout 2 (addresses 2 and 3), signal 5; positions chosen so that every route
// step changes something.
inline const char* const Accessories = R"([magnetartikel]
version
 .minor=1
artikel
 .id=1
 .name=W1
 .typ=rechtsweiche
 .stellung=0
 .dectyp=mm2
artikel
 .id=2
 .name=W2
 .typ=dreiwegweiche
 .stellung=0
 .dectyp=mm2
artikel
 .id=5
 .name=S5
 .typ=lichtsignal_HP01
 .stellung=0
 .dectyp=mm2
)";

// Route 1: W1 straight, after 0.3 s S5 green, after 0.2 s W2 to its third position. Route 2 runs route 1
// after 0.1 s, then sets W1 back. Routes 3 and 4 reference each other.
inline const char* const Routes = R"([fahrstrassen]
version
 .minor=4
fahrstrasse
 .id=1
 .name=Einfahrt
 .item
 ..typ=mag
 ..magnetartikel=1
 ..stellung=1
 .item
 ..typ=mag
 ..magnetartikel=5
 ..stellung=1
 ..sekunde=0.3
 .item
 ..typ=mag
 ..magnetartikel=2
 ..stellung=2
 ..sekunde=0.2
fahrstrasse
 .id=2
 .name=Durchfahrt
 .item
 ..fsverweis=1
 ..sekunde=0.1
 .item
 ..typ=mag
 ..magnetartikel=1
 ..stellung=0
fahrstrasse
 .id=3
 .name=Kreis A
 .item
 ..fsverweis=4
fahrstrasse
 .id=4
 .name=Kreis B
 .item
 ..fsverweis=3
)";

inline const char* const TrackPlan = R"([gleisbild]
version
 .major=1
groesse
seite
 .name=Bahnhof
)";

inline const char* const StationPage = R"([gleisbildseite]
version
 .major=1
element
 .id=0x102
 .typ=s88kontakt
 .artikel=7
 .deviceId=0x0
 .text=Gleis 1
element
 .id=0x103
 .typ=rechtsweiche
 .artikel=2
 .text=W1
element
 .id=0x104
 .typ=fahrstrasse
 .artikel=1
)";

inline sim::StationLayout inlineLayout() {
    return sim::StationLayout::fromFiles({{"lokomotive.cs2", Locomotives},
                                          {"magnetartikel.cs2", Accessories},
                                          {"fahrstrassen.cs2", Routes},
                                          {"gleisbild.cs2", TrackPlan},
                                          {"gleisbilder/Bahnhof.cs2", StationPage}});
}

inline station::StationSettings fastSettings() {
    station::StationSettings settings;
    settings.commands.timeout = 200ms;
    settings.commands.retries = 1;
    settings.streamIdle = 500ms;
    return settings;
}

inline sim::SimulatedStation::Options stationOptions() {
    sim::SimulatedStation::Options options;
    options.uid = CentralStationUid;
    return options;
}

// The simulated station, the session on the app's end of the pair and the railway, joined and open.
class ModelBench {
public:
    explicit ModelBench(sim::StationLayout layout = inlineLayout(),
                        sim::SimulatedStation::Options options = stationOptions())
        : station(std::move(layout), options), session(appBus, fastSettings()), railway(session) {
        transport::LoopbackTransport::join(stationEnd, appEnd);
        QObject::connect(&station, &sim::SimulatedStation::framesEmitted, &stationEnd,
                         [this](const std::vector<can::CanFrame>& frames) {
                             if (!muted)
                                 stationEnd.sendBatch(frames);
                         });
        QObject::connect(&stationEnd, &transport::Transport::framesReceived, &station,
                         [this](const std::vector<can::CanFrame>& frames) {
                             for (const auto& frame : frames)
                                 if (stalled)
                                     held.push_back(frame);
                                 else if (!deaf)
                                     station.receive(frame);
                         });
        stationEnd.open();
        appEnd.open();
    }

    // Runs the start-up and loads the railway from it; false when it did not finish in time.
    bool start() {
        station::StartupOptions options;
        options.deviceWindow = 150ms;
        station::StartupSequence startup(session, options);
        QObject::connect(&startup, &station::StartupSequence::ready, &railway,
                         [this](const station::StartupResult& result) { railway.load(result); });
        QSignalSpy loaded(&railway, &Railway::loaded);
        startup.start();
        return waitFor([&] { return loaded.count() == 1; });
    }

    // The station stays connected but hears nothing any more (and so answers nothing).
    bool deaf = false;
    // The station stops reading without closing (a frozen screen, a Wi-Fi stall); wake() makes it read
    // everything that arrived meanwhile at once, as a stalled CS2 does when it comes back.
    void stall() { stalled = true; }
    void wake() {
        stalled = false;
        const std::vector<can::CanFrame> frames = std::move(held);
        held.clear();
        for (const auto& frame : frames)
            station.receive(frame);
    }
    bool stalled = false;
    std::vector<can::CanFrame> held;
    // What the station says is lost on the way (the app hears nothing of it).
    bool muted = false;
    transport::LoopbackTransport stationEnd{QStringLiteral("station")};
    transport::LoopbackTransport appEnd{QStringLiteral("app")};
    bus::Bus appBus{appEnd, busreading::BusProfile::centralStation()};
    sim::SimulatedStation station;
    station::StationSession session;
    Railway railway;
};

} // namespace stellwerk::model::test
