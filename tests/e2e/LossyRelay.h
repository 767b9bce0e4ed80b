#pragma once

#include <QByteArray>
#include <QHostAddress>
#include <QObject>
#include <QUdpSocket>
#include <cstdint>

namespace stellwerk::e2e {

// Stands between a UDP station and the app and passes on only every other datagram the station sends:
// a station whose answers get lost half of the time.
class LossyRelay : public QObject {
public:
    explicit LossyRelay(std::uint16_t appPort) : appPort_(appPort) {
        bound_ = socket_.bind(QHostAddress::LocalHost, 0);
        connect(&socket_, &QUdpSocket::readyRead, this, &LossyRelay::pass);
    }

    bool bound() const { return bound_; }
    std::uint16_t port() const { return socket_.localPort(); }
    int passed() const { return passed_; }
    int dropped() const { return dropped_; }

private:
    void pass() {
        while (socket_.hasPendingDatagrams()) {
            QByteArray datagram(qsizetype(socket_.pendingDatagramSize()), '\0');
            socket_.readDatagram(datagram.data(), datagram.size());
            if ((passed_ + dropped_) % 2 == 1) {
                ++dropped_;
                continue;
            }
            ++passed_;
            socket_.writeDatagram(datagram, QHostAddress::LocalHost, appPort_);
        }
    }

    std::uint16_t appPort_;
    QUdpSocket socket_;
    int passed_ = 0;
    int dropped_ = 0;
    bool bound_ = false;
};

} // namespace stellwerk::e2e
