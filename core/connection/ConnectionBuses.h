#pragma once

#include "busreading/FrameClassifier.h"
#include "can/CanFrame.h"
#include "transport/Transport.h"

#include <QObject>
#include <QString>
#include <cstdint>
#include <vector>

namespace stellwerk::connection {

class StationLink;

// One bus of the connection, as the monitor shows it.
struct BusInfo {
    QString place; // "socketcan/can1", "127.0.0.1:15731"; the station's place on the station's bus
    busreading::BusProfile profile; // what is expected on it
    bool station = false;           // the bus the command station is reached by (always bus 0)
};

// The buses' face of a connection, all the bus monitor and the traffic gauge may see: the buses held open
// (the station's first), whether each is connected, what came over each, and their frames as they pass.
// The StationConnection owns it (buses()) and has it follow its buses as they open and close.
class ConnectionBuses final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConnectionBuses)

public:
    explicit ConnectionBuses(QObject* parent = nullptr);
    ~ConnectionBuses() override;

    // The buses held open, the station's first; empty while disconnected.
    std::vector<BusInfo> list() const;
    // Whether bus `index` is connected now.
    bool isBusConnected(int index) const;
    // Frames received on bus `index` that belong to `protocol` (Foreign: to none expected there).
    std::uint64_t busFrames(int index, busreading::Protocol protocol) const;
    // What the transport to the station counted (frames in and out, ...); zeros while there is none.
    transport::TransportCounters stationCounters() const;

signals:
    // The buses were opened (after connectTo) or closed.
    void busesChanged();
    // Frames on the wire, for a bus monitor: one signal per batch a transport read (`outgoing` false) and
    // per block it wrote after pacing (`outgoing` true), in the order they passed; `bus` is the index in
    // list().
    void busFramesSeen(int bus, const std::vector<stellwerk::can::CanFrame>& frames, bool outgoing);
    // The same for the station's bus alone.
    void stationFramesSeen(const std::vector<stellwerk::can::CanFrame>& frames, bool outgoing);

private:
    friend class StationConnection;
    // The connection opened these buses: their frames pass through here from now on.
    void follow(const StationLink& link);
    // The connection closed them (busesChanged when there were any).
    void release();

    const StationLink* link_ = nullptr;
};

} // namespace stellwerk::connection
