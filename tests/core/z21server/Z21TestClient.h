#pragma once

// A Z21 client of the tests' own, written from the codec: it sends requests (or any bytes) to the server
// over loopback and keeps every reply it reads.

#include "ReceivedMessages.h"
#include "z21/ReplyCodec.h"
#include "z21/RequestCodec.h"

#include <QNetworkDatagram>
#include <QTest>
#include <QUdpSocket>
#include <optional>
#include <span>
#include <vector>

namespace stellwerk::z21server::test {

class Z21TestClient : public support::ReceivedMessages<z21::Reply> {
public:
    explicit Z21TestClient(quint16 serverPort) : port_(serverPort) {
        socket_.bind(QHostAddress::LocalHost, 0);
        QObject::connect(&socket_, &QUdpSocket::readyRead, &socket_, [this] { read(); });
    }

    void send(const z21::RequestBody& request) { sendBytes(z21::encodeRequest(request)); }
    void sendBytes(const std::vector<std::uint8_t>& bytes) {
        socket_.writeDatagram(reinterpret_cast<const char*>(bytes.data()), qint64(bytes.size()),
                              QHostAddress::LocalHost, port_);
    }
    quint16 localPort() const { return socket_.localPort(); }

    // The last loco info of an address.
    std::optional<z21::LocoInfo> locoInfo(std::uint16_t address) const {
        std::optional<z21::LocoInfo> found;
        for (const z21::LocoInfo& info : all<z21::LocoInfo>())
            if (info.address == address)
                found = info;
        return found;
    }

private:
    void read() {
        while (socket_.hasPendingDatagrams()) {
            const QNetworkDatagram datagram = socket_.receiveDatagram();
            const QByteArray data = datagram.data();
            const z21::DatagramReplies read = z21::readReplies(
                std::span(reinterpret_cast<const std::uint8_t*>(data.constData()), std::size_t(data.size())));
            received.insert(received.end(), read.replies.begin(), read.replies.end());
        }
    }

    QUdpSocket socket_;
    quint16 port_;
};

} // namespace stellwerk::z21server::test
