#pragma once

#include "sim/SimulatedBus.h"
#include "transport/FrameAssembler.h"
#include "transport/NetworkFraming.h"

#include <QHostAddress>
#include <QObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <map>
#include <memory>
#include <vector>

namespace stellwerk::support {

// Stands for a further bus with devices on it in tests: a CAN-to-TCP gateway on a free loopback port whose
// CAN side is a SimulatedBus. Devices attached to `bus` (simulated RO modules, ORC devices) are its peers:
// what a client writes reaches them, what they answer reaches every client, in the 13-byte network form.
// It can be unplugged and plugged in again on the same port.
class DeviceBusPeer final : public QObject {
public:
    DeviceBusPeer() {
        connect(&bus, &sim::SimulatedBus::framesCarried, this,
                [this](const std::vector<can::CanFrame>& frames) {
                    const QByteArray bytes = transport::encodeFrames(frames);
                    for (const auto& [socket, assembler] : clients_)
                        socket->write(bytes);
                });
    }
    bool listen() {
        if (!server_.listen(QHostAddress::LocalHost, port_))
            return false;
        port_ = server_.serverPort();
        connect(&server_, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket* socket = server_.nextPendingConnection())
                accept(socket);
        });
        return true;
    }
    // Closes the port and drops every client, as an unplugged gateway does.
    void stop() {
        server_.close();
        disconnect(&server_, nullptr, this, nullptr);
        for (auto& [socket, assembler] : clients_) {
            socket->abort();
            socket->deleteLater();
        }
        clients_.clear();
    }
    bool hasClient() const { return !clients_.empty(); }
    QString url() const { return QStringLiteral("tcp://127.0.0.1:%1").arg(port_); }
    std::uint16_t port() const { return port_; }

    sim::SimulatedBus bus;
    std::vector<can::CanFrame> written; // every frame the app wrote to this bus

private:
    void accept(QTcpSocket* socket) {
        clients_[socket] = std::make_unique<transport::FrameAssembler>();
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] {
            const auto client = clients_.find(socket);
            if (client == clients_.end())
                return;
            const QByteArray bytes = socket->readAll();
            std::vector<can::CanFrame> frames;
            client->second->feed(transport::asBytes(bytes), frames);
            written.insert(written.end(), frames.begin(), frames.end());
            bus.putFromOutside(frames);
        });
    }

    QTcpServer server_;
    std::map<QTcpSocket*, std::unique_ptr<transport::FrameAssembler>> clients_;
    std::uint16_t port_ = 0;
};

} // namespace stellwerk::support
