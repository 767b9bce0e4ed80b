#pragma once

#include "bus/Bus.h"
#include "connection/DeviceSessions.h"
#include "connection/HandheldConnection.h"
#include "station/StartupSequence.h"
#include "station/StationSession.h"
#include "transport/LocalPeer.h"
#include "transport/Transport.h"

#include <QObject>
#include <memory>
#include <vector>

namespace stellwerk::connection {

// Everything one connection owns, torn down together: the start-up and the session before the buses they
// read, the buses before their transports, the transports before the local station they talk to. The device
// sessions go before the buses too. Bus 0 is the station's; further ones (a USB-CAN adapter with modules)
// follow in the order given.
class StationLink final : public QObject {
public:
    ~StationLink() override {
        startup.reset();
        session.reset();
        handhelds.reset();
        devices.reset();
        buses.clear();
        transports.clear();
        local.reset();
    }

    bus::Bus& addBus(std::unique_ptr<transport::Transport> transport, busreading::BusProfile profile,
                     QString place) {
        transports.push_back(std::move(transport));
        buses.push_back(std::make_unique<bus::Bus>(*transports.back(), std::move(profile), std::move(place)));
        return *buses.back();
    }
    bus::Bus& stationBus() const { return *buses.front(); }
    transport::Transport& stationTransport() const { return *transports.front(); }

    // Stops every signal from the link's parts to `receiver`.
    void detach(const QObject* receiver) const {
        for (const auto& transport : transports)
            QObject::disconnect(transport.get(), nullptr, receiver, nullptr);
        for (const auto& bus : buses)
            QObject::disconnect(bus.get(), nullptr, receiver, nullptr);
        if (startup)
            QObject::disconnect(startup.get(), nullptr, receiver, nullptr);
        if (session)
            QObject::disconnect(&session->liveness(), nullptr, receiver, nullptr);
        if (handhelds)
            QObject::disconnect(&handhelds->master(), nullptr, receiver, nullptr);
        if (devices)
            QObject::disconnect(devices.get(), nullptr, receiver, nullptr);
    }

    std::unique_ptr<transport::LocalPeer> local;
    std::vector<std::unique_ptr<transport::Transport>> transports;
    std::vector<std::unique_ptr<bus::Bus>> buses;
    std::unique_ptr<station::StationSession> session;
    std::unique_ptr<HandheldConnection> handhelds; // Stellwerk's part in the MS1 handhelds' conversation
    std::unique_ptr<DeviceSessions> devices;       // the ORC central and the RO modules, on their buses
    std::unique_ptr<station::StartupSequence> startup;
};

} // namespace stellwerk::connection
