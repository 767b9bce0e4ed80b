#pragma once

#include "transport/NetworkFraming.h"
#include "transport/Reconnector.h"
#include "transport/Transport.h"
#include "transport/TransportSettings.h"

#include <QByteArray>
#include <QHostAddress>

class QHostInfo;
class QUdpSocket;

namespace stellwerk::transport {

// A CS2 or gateway reached by UDP: one 13-byte frame per datagram to port 15731 (unicast or broadcast),
// datagrams of n x 13 bytes received on port 15730; anything else that arrives is counted and dropped.
class UdpTransport final : public Transport {
    Q_OBJECT

public:
    explicit UdpTransport(UdpSettings settings, QObject* parent = nullptr);
    ~UdpTransport() override;

    void open() override;
    void close() override;
    bool carriesStandardFrames() const override { return false; }
    QString description() const override;
    const UdpSettings& settings() const { return settings_; }
    // The port frames are received on once connected (the one the system chose when settings ask for 0).
    std::uint16_t boundPort() const;

protected:
    std::size_t writeFrames(std::span<const can::CanFrame> frames) override;

private:
    void resolveStation();
    void onLookup(const QHostInfo& info);
    void bindSocket();
    void onReadyRead();
    bool readDatagram(std::vector<can::CanFrame>& frames);
    void countBadDatagram(const DatagramContent& content, std::size_t size, const QString& sender);
    void attemptFailed(const QString& reason);
    void stopLookup();
    void reportSendFailure(bool failed);

    UdpSettings settings_;
    QUdpSocket* socket_;
    Reconnector reconnector_;
    QHostAddress station_;
    int lookupId_ = -1;
    bool sendFailing_ = false;
    QByteArray datagram_;
};

} // namespace stellwerk::transport
