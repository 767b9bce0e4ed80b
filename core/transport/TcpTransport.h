#pragma once

#include "transport/FrameAssembler.h"
#include "transport/Reconnector.h"
#include "transport/Transport.h"
#include "transport/TransportSettings.h"

#include <QByteArray>

class QTcpSocket;

namespace stellwerk::transport {

// A CS2 or gateway reached over TCP (port 15731): 13-byte frames in a byte stream, cut into frames
// whatever the segmentation, and a connection that is made again with back-off when the peer goes away.
class TcpTransport final : public Transport {
    Q_OBJECT

public:
    explicit TcpTransport(TcpSettings settings, QObject* parent = nullptr);

    // Bytes the socket may hold beyond what the kernel took before the transport counts the wire as busy
    // and keeps further frames in its send queue (where a given-up command can still be withdrawn).
    static constexpr qint64 BusyBytes = 4096;

    void open() override;
    void close() override;
    // Aborts with a reset (RST), which discards what the station has not read yet, and reconnects.
    bool resetConnection(const QString& reason) override;
    bool carriesStandardFrames() const override { return false; }
    QString description() const override;
    const TcpSettings& settings() const { return settings_; }

protected:
    std::size_t writeFrames(std::span<const can::CanFrame> frames) override;

private:
    void connectToStation();
    void onConnected();
    void onReadyRead();
    void connectionLost(const QString& reason);
    void onBytesWritten();

    TcpSettings settings_;
    QTcpSocket* socket_;
    FrameAssembler assembler_;
    Reconnector reconnector_;
};

} // namespace stellwerk::transport
