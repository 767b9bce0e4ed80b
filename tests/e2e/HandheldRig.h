#pragma once

// Issue 14 end to end: MS1 handhelds on the station's bus and Stellwerk as their master or their watcher.
// The station's side is a simulated bus with the simulated CS2 and two simulated MS1s behind the station's
// server; the app's side is a StationConnection with its railway and the handhelds' master, as the GUI
// holds them; between them real loopback sockets or Qt's virtualcan bus.

#include "E2eSupport.h"
#include "StationLog.h"
#include "connection/StationConnection.h"
#include "mcan/Codec.h"
#include "mcanhandhelds/HandheldMaster.h"
#include "model/Railway.h"
#include "model/RailwayHandhelds.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedMs1.h"
#include "sim/StationHandhelds.h"
#include "transport/TransportAddress.h"

#include <memory>
#include <string>
#include <vector>

namespace stellwerk::e2e {

inline constexpr std::uint32_t FirstMs1 = 0x000204B3;
inline constexpr std::uint32_t SecondMs1 = 0x000204C7;

// A handheld that polls every 20 ms and tries a lost login again after 150 ms (the documents: 250 ms, 5 s).
inline sim::SimulatedMs1::Options quickMs1(std::uint32_t uid, std::string name) {
    sim::SimulatedMs1::Options options;
    options.identity.uid = uid;
    options.identity.name = std::move(name);
    options.timing.pollPeriod = 20ms;
    options.timing.loginRetry = 150ms;
    return options;
}

// A master that calls a handheld silent after 300 ms and drops it after 5 polls 20 ms apart.
inline mcanhandhelds::MasterSettings quickMaster() {
    mcanhandhelds::MasterSettings settings;
    settings.silentAfter = 300ms;
    settings.masterPollEvery = 20ms;
    settings.masterPolls = 5;
    settings.tick = 10ms;
    return settings;
}

// The station's side: the simulated CS2 and two MS1s on one bus behind the station's server. With
// `stationIsMaster` the CS2 is the handhelds' master, as a real one is; without, it answers a ping as a
// Gleisbox does, and the handhelds have no master unless Stellwerk is theirs.
class HandheldBus {
public:
    HandheldBus(Wire wire, bool stationIsMaster)
        : station(sim::StationLayout::demo(), stationOptions(stationIsMaster)), wire_(wire) {
        bus.attach(station);
        if (stationIsMaster)
            addStationMaster();
        bus.attach(first);
        bus.attach(second);
        if (wire_ == Wire::Udp)
            appUdpPort_ = freeUdpPort();
    }

    // The CS2's master side joins the bus (a Central Station appears).
    void addStationMaster() {
        stationMaster = std::make_unique<sim::StationHandhelds>(station, quickMaster());
        bus.attach(*stationMaster);
    }

    // (Re)opens the station's listeners on the ports of the last time (free ones the first time).
    bool listen() {
        server = std::make_unique<sim::StationServer>(station, bus, serverSettings());
        if (!server->listen()) {
            ADD_FAILURE() << server->errorString().toStdString();
            return false;
        }
        stationUdpPort_ = server->udpPort();
        return true;
    }
    void stopServer() { server.reset(); }

    // The address the app connects to.
    QString url() const {
        if (wire_ == Wire::Udp)
            return QStringLiteral("udp://127.0.0.1:%1?listen=%2").arg(stationUdpPort_).arg(appUdpPort_);
        return transport::transportUrl(virtualBus());
    }

    sim::SimulatedBus bus;
    sim::SimulatedStation station;
    std::unique_ptr<sim::StationHandhelds> stationMaster;
    sim::SimulatedMs1 first{quickMs1(FirstMs1, "MS1 A")};
    sim::SimulatedMs1 second{quickMs1(SecondMs1, "MS1 B")};
    std::unique_ptr<sim::StationServer> server;

private:
    static sim::SimulatedStation::Options stationOptions(bool stationIsMaster) {
        sim::SimulatedStation::Options options;
        options.handheldMaster = stationIsMaster;
        return options;
    }

    sim::StationServerSettings serverSettings() const {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.tcp = false;
        settings.udp = wire_ == Wire::Udp;
        settings.udpPort = stationUdpPort_;
        settings.udpReplyHost = QHostAddress::LocalHost;
        settings.udpReplyPort = appUdpPort_;
        if (wire_ == Wire::VirtualCan)
            settings.canBus = virtualBus();
        return settings;
    }

    Wire wire_;
    std::uint16_t appUdpPort_ = 0;
    std::uint16_t stationUdpPort_ = 0;
};

// The app's side as the GUI holds it: the connection, the railway made and loaded at each session, the
// handhelds driving it, and the M-CAN frames Stellwerk sent.
class HandheldApp {
public:
    explicit HandheldApp(connection::HandheldRole role) : connection(settings(role)) {
        QObject::connect(&connection, &connection::StationConnection::sessionStarted, &connection,
                         [this](station::StationSession* session) {
                             railway = std::make_unique<model::Railway>(*session);
                             if (mcanhandhelds::HandheldMaster* master = connection.handhelds().master())
                                 new model::RailwayHandhelds(*railway, *master, railway.get());
                         });
        QObject::connect(&connection, &connection::StationConnection::configurationLoaded, &connection,
                         [this](const station::StartupResult& result) { railway->load(result); });
        QObject::connect(&connection.buses(), &connection::ConnectionBuses::stationFramesSeen, &connection,
                         [this](const std::vector<can::CanFrame>& frames, bool outgoing) {
                             for (const can::CanFrame& frame : frames) {
                                 if (outgoing && mcan::isMcan(frame))
                                     mcanSent.push_back(frame);
                             }
                         });
    }

    bool ready(int timeoutMs = 3 * WaitMs) {
        return waitFor(
            [&] {
                return connection.state() == connection::StationConnection::State::Ready && railway &&
                       railway->isStateReported();
            },
            timeoutMs);
    }

    mcanhandhelds::HandheldMaster& master() const { return *connection.handhelds().master(); }

    // The handheld as the app shows it, when it knows it.
    std::optional<mcanhandhelds::Handheld> handheld(std::uint32_t uid) const {
        for (const mcanhandhelds::Handheld& h : master().handhelds())
            if (h.uid == uid)
                return h;
        return std::nullopt;
    }
    bool shows(std::uint32_t uid, mcanhandhelds::HandheldState state) const {
        const auto h = handheld(uid);
        return h && h->state == state;
    }

    const model::Locomotive& loco(std::uint32_t id) const { return *railway->locomotive(id); }

    std::vector<can::CanFrame> mcanSent; // first: the railway's end still sends (the handhelds learn it)
    connection::StationConnection connection;
    std::unique_ptr<model::Railway> railway;

private:
    static connection::ConnectionSettings settings(connection::HandheldRole role) {
        connection::ConnectionSettings settings;
        settings.session.uid = 0x53574B03;
        settings.session.commands = {100ms, 2};
        settings.session.liveness = {200ms, 3};
        settings.startup.deviceWindow = 100ms;
        settings.startup.readStatusData = false;
        settings.handhelds.role = role;
        settings.handhelds.master = quickMaster();
        return settings;
    }
};

// An MS1 that is online and granted the first locomotive of its stack.
inline bool drivesFirstLoco(sim::SimulatedMs1& ms1) {
    if (!waitFor(
            [&] { return ms1.phase() == sim::SimulatedMs1::Phase::Online && !ms1.memory().stack.empty(); }))
        return false;
    if (!ms1.takeLoco(0))
        return false;
    return waitFor([&] { return ms1.memory().control == sim::Ms1Control::Granted; });
}

} // namespace stellwerk::e2e
