#pragma once

#include "can/FrameAssembler.h"
#include "can/Reconnector.h"
#include "can/Transport.h"
#include "can/TransportSettings.h"

#include <QByteArray>

class QTcpSocket;

namespace stellwerk::can {

// A CS2 or gateway reached over TCP (port 15731): 13-byte frames in a byte stream, cut into frames
// whatever the segmentation, and a connection that is made again with back-off when the peer goes away.
class TcpTransport final : public Transport {
    Q_OBJECT

public:
    explicit TcpTransport(TcpSettings settings, QObject* parent = nullptr);

    void open() override;
    void close() override;
    QString description() const override;
    const TcpSettings& settings() const { return settings_; }

protected:
    std::size_t writeFrames(std::span<const cs2::CanFrame> frames) override;

private:
    void connectToStation();
    void onConnected();
    void onReadyRead();
    void connectionLost(const QString& reason);

    TcpSettings settings_;
    QTcpSocket* socket_;
    FrameAssembler assembler_;
    Reconnector reconnector_;
};

} // namespace stellwerk::can
