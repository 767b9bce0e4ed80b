#pragma once

#include "transport/FrameAssembler.h"

#include <QObject>
#include <QTcpServer>
#include <cstdint>
#include <map>
#include <memory>

class QTcpSocket;

namespace stellwerk::sim {

class SimulatedBus;

// A CAN-to-TCP gateway in front of a SimulatedBus (a can2lan box with devices behind it): what a client
// writes in the 13-byte network form goes onto the bus, what the bus's peers send goes to every client.
// The embedded station's device bus is reached through it like any further bus.
class BusGateway final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusGateway)

public:
    explicit BusGateway(SimulatedBus& bus, QObject* parent = nullptr);
    ~BusGateway() override;

    // Listens on `port` of 127.0.0.1 (0: a free one); false (with errorString()) when it cannot.
    bool listen(std::uint16_t port = 0);
    QString errorString() const { return server_.errorString(); }
    std::uint16_t port() const { return server_.serverPort(); }

private:
    void accept();

    SimulatedBus& bus_;
    QTcpServer server_;
    std::map<QTcpSocket*, std::unique_ptr<transport::FrameAssembler>> clients_;
};

} // namespace stellwerk::sim
