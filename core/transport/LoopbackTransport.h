#pragma once

#include "transport/Transport.h"

#include <QPointer>
#include <vector>

class QTimer;

namespace stellwerk::transport {

// Two ends of a CAN bus inside one process, for the embedded simulator and for tests: frames sent on one
// end arrive on the other, batched per turn of the event loop. Both ends live on the same thread.
class LoopbackTransport final : public Transport {
    Q_OBJECT

public:
    explicit LoopbackTransport(QString name = QStringLiteral("loopback"), QObject* parent = nullptr);
    ~LoopbackTransport() override;

    // Joins two ends (each is then connected while both are open).
    static void join(LoopbackTransport& first, LoopbackTransport& second);

    void open() override;
    void close() override;
    QString description() const override;

protected:
    std::size_t writeFrames(std::span<const can::CanFrame> frames) override;

private:
    void peerOpened();
    void peerClosed();
    void arrive(std::span<const can::CanFrame> frames);
    void deliverArrived();

    QString name_;
    QPointer<LoopbackTransport> peer_;
    std::vector<can::CanFrame> arrived_;
    QTimer* deliveryTimer_;
    bool hasConnected_ = false;
};

} // namespace stellwerk::transport
