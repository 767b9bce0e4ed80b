#include "sim/BusGateway.h"

#include "sim/SimulatedBus.h"
#include "transport/NetworkFraming.h"

#include <QTcpSocket>

namespace stellwerk::sim {

BusGateway::BusGateway(SimulatedBus& bus, QObject* parent) : QObject(parent), bus_(bus) {
    connect(&bus_, &SimulatedBus::framesCarried, this, [this](const std::vector<can::CanFrame>& frames) {
        const QByteArray bytes = transport::encodeFrames(frames);
        for (const auto& [socket, assembler] : clients_)
            socket->write(bytes);
    });
    connect(&server_, &QTcpServer::newConnection, this, &BusGateway::accept);
}

// The clients go before the map that knows them (they are the server's children, which go later).
BusGateway::~BusGateway() {
    for (const auto& [socket, assembler] : clients_) {
        disconnect(socket, nullptr, this, nullptr);
        delete socket;
    }
    clients_.clear();
}

bool BusGateway::listen(std::uint16_t port) {
    return server_.listen(QHostAddress::LocalHost, port);
}

void BusGateway::accept() {
    while (QTcpSocket* socket = server_.nextPendingConnection()) {
        clients_[socket] = std::make_unique<transport::FrameAssembler>();
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] {
            const auto client = clients_.find(socket);
            if (client == clients_.end())
                return;
            const QByteArray bytes = socket->readAll();
            std::vector<can::CanFrame> frames;
            client->second->feed(transport::asBytes(bytes), frames);
            bus_.putFromOutside(frames);
        });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            clients_.erase(socket);
            socket->deleteLater();
        });
    }
}

} // namespace stellwerk::sim
