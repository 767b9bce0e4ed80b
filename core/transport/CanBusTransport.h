#pragma once

#include "transport/Reconnector.h"
#include "transport/Transport.h"
#include "transport/TransportSettings.h"

#include <QCanBusDevice>
#include <vector>

namespace stellwerk::transport {

// A CAN interface offered by Qt's CAN bus plugins, as the interface list for the connection dialog.
struct CanBusInterface {
    QString plugin;
    QString name;
    QString description;
};

// The CS2 bus reached through any CAN interface Qt has a plugin for (socketcan, peakcan, virtualcan, ...):
// 29-bit frames, one device write per frame, device errors passed on and the device made again after it
// failed or went away.
class CanBusTransport final : public Transport {
    Q_OBJECT

public:
    explicit CanBusTransport(CanBusSettings settings, QObject* parent = nullptr);
    ~CanBusTransport() override;

    void open() override;
    void close() override;
    QString description() const override;
    const CanBusSettings& settings() const { return settings_; }

    // Every interface every plugin reports now (plugins whose driver is missing report none).
    static std::vector<CanBusInterface> availableInterfaces();

protected:
    std::size_t writeFrames(std::span<const can::CanFrame> frames) override;

private:
    void createDevice();
    void watchDevice();
    void onDeviceState(QCanBusDevice::CanBusDeviceState deviceState);
    void onDeviceError(QCanBusDevice::CanBusError error);
    void onFramesReceived();
    void connectionLost(const QString& reason);
    void dropDevice();
    void reportWriteFailure(bool failed);

    CanBusSettings settings_;
    QCanBusDevice* device_ = nullptr;
    Reconnector reconnector_;
    bool writeFailing_ = false;
};

} // namespace stellwerk::transport
