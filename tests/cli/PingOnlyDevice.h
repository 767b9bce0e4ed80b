#pragma once

#include "cs2/Codec.h"
#include "transport/FrameAssembler.h"
#include "transport/NetworkFraming.h"

#include <QHostAddress>
#include <QTcpSocket>
#include <QTest>
#include <cstdint>
#include <vector>

namespace stellwerk::cli::test {

// Another program on the station's bus (a PC program such as the CS2 PC software, device type 0xEEEE):
// a TCP client of the station that answers every ping with its identity and ignores everything else,
// status data requests included.
class PingOnlyDevice {
public:
    static constexpr std::uint32_t Uid = 0x50435057;
    static constexpr std::uint16_t Type = 0xEEEE;

    explicit PingOnlyDevice(std::uint16_t stationTcpPort) {
        QObject::connect(&socket_, &QTcpSocket::readyRead, &socket_, [this] { answer(); });
        socket_.connectToHost(QHostAddress::LocalHost, stationTcpPort);
        connected_ = socket_.waitForConnected(3000);
    }

    bool connected() const { return connected_; }
    int pingsAnswered() const { return answered_; }

private:
    void answer() {
        const QByteArray bytes = socket_.readAll();
        std::vector<can::CanFrame> frames;
        assembler_.feed(transport::asBytes(bytes), frames);
        for (const can::CanFrame& frame : frames) {
            const cs2::DecodeResult message = cs2::decode(frame);
            if (!message || message->response || !std::holds_alternative<cs2::Ping>(message->body))
                continue;
            const cs2::Message reply{0, true, 0x0300, cs2::Ping{cs2::DeviceIdentity{Uid, 4, 1, Type}}};
            const can::CanFrame encoded = cs2::encode(reply);
            socket_.write(transport::encodeFrames(std::span(&encoded, 1)));
            ++answered_;
        }
    }

    QTcpSocket socket_;
    transport::FrameAssembler assembler_;
    bool connected_ = false;
    int answered_ = 0;
};

} // namespace stellwerk::cli::test
