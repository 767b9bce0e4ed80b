#pragma once

#include "can/CanFrame.h"
#include "transport/NetworkFraming.h"

#include <QHostAddress>
#include <QObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <memory>
#include <vector>

namespace stellwerk::support {

// Stands for a further bus in tests: a CAN-to-TCP gateway with modules behind it, on a free loopback
// port, sending frames in the 13-byte network form and recording every byte the app writes to it. It
// can go away and come back on the same port.
class ModuleBusPeer final : public QObject {
public:
    bool listen() {
        if (!server_.listen(QHostAddress::LocalHost, port_))
            return false;
        port_ = server_.serverPort();
        connect(&server_, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket* socket = server_.nextPendingConnection()) {
                connect(socket, &QTcpSocket::readyRead, this,
                        [this, socket] { written += socket->readAll(); });
                clients_.push_back(socket);
            }
        });
        return true;
    }
    // Closes the port and drops every client, as an unplugged gateway does.
    void stop() {
        server_.close();
        disconnect(&server_, nullptr, this, nullptr);
        for (QTcpSocket* socket : clients_) {
            socket->abort();
            socket->deleteLater();
        }
        clients_.clear();
    }
    void send(const std::vector<can::CanFrame>& frames) { sendBytes(transport::encodeFrames(frames)); }
    void sendBytes(const QByteArray& bytes) {
        for (QTcpSocket* socket : clients_)
            socket->write(bytes);
    }
    bool hasClient() const { return !clients_.empty(); }
    QString url() const { return QStringLiteral("tcp://127.0.0.1:%1").arg(port_); }
    std::uint16_t port() const { return port_; }

    QByteArray written; // everything the app wrote to this bus

private:
    QTcpServer server_;
    std::vector<QTcpSocket*> clients_;
    std::uint16_t port_ = 0;
};

} // namespace stellwerk::support
