#include "transport/CanBusTransport.h"

#include "transport/DurationText.h"
#include "transport/TransportAddress.h"

#include <QCanBus>
#include <QCanBusFrame>
#include <QStringList>
#include <QVariant>
#include <algorithm>
#include <optional>

namespace stellwerk::transport {

using can::CanFrame;

namespace {

QCanBusFrame toCanBus(const CanFrame& frame) {
    const auto payload = frame.payload();
    QCanBusFrame canBusFrame(
        frame.id, QByteArray(reinterpret_cast<const char*>(payload.data()), qsizetype(payload.size())));
    // Set explicitly: QCanBusFrame guesses the format from the id, which would send a 29-bit frame with a
    // small id as an 11-bit one.
    canBusFrame.setExtendedFrameFormat(frame.extended);
    return canBusFrame;
}

// Classic data frames of at most 8 bytes, standard (11-bit) or extended (29-bit); remote, error and CAN FD
// frames belong to no protocol Stellwerk speaks.
std::optional<CanFrame> fromCanBus(const QCanBusFrame& canBusFrame) {
    const QByteArray payload = canBusFrame.payload();
    if (canBusFrame.frameType() != QCanBusFrame::DataFrame || canBusFrame.hasFlexibleDataRateFormat() ||
        payload.size() > 8)
        return std::nullopt;
    CanFrame frame;
    frame.extended = canBusFrame.hasExtendedFrameFormat();
    frame.id = canBusFrame.frameId() & frame.idMask();
    frame.dlc = std::uint8_t(payload.size());
    std::copy(payload.begin(), payload.end(), frame.data.begin());
    return frame;
}

} // namespace

CanBusTransport::CanBusTransport(CanBusSettings settings, QObject* parent)
    : Transport(parent), settings_(std::move(settings)),
      reconnector_(
          this, [this] { createDevice(); },
          [this] {
              connectionLost(
                  tr("no connection within %1").arg(durationText(settings_.reconnect.attemptTimeout)));
          }) {
    reconnector_.setTiming(settings_.reconnect);
}

CanBusTransport::~CanBusTransport() {
    dropDevice();
}

void CanBusTransport::open() {
    if (state() != State::Closed)
        return;
    setState(State::Connecting);
    reconnector_.start();
}

void CanBusTransport::close() {
    if (state() == State::Closed)
        return;
    setState(State::Closed);
    reconnector_.stop();
    dropDevice();
}

QString CanBusTransport::description() const {
    return transportUrl(settings_);
}

std::vector<CanBusInterface> CanBusTransport::availableInterfaces() {
    std::vector<CanBusInterface> interfaces;
    for (const QString& plugin : QCanBus::instance()->plugins()) {
        for (const QCanBusDeviceInfo& info : QCanBus::instance()->availableDevices(plugin))
            interfaces.push_back({plugin, info.name(), info.description()});
    }
    return interfaces;
}

// One device write per frame: a CAN controller sends frames one at a time.
std::size_t CanBusTransport::writeFrames(std::span<const CanFrame> frames) {
    std::size_t written = 0;
    for (const CanFrame& frame : frames) {
        if (!device_ || device_->state() != QCanBusDevice::ConnectedState)
            break;
        const bool ok = device_->writeFrame(toCanBus(frame));
        reportWriteFailure(!ok);
        written += ok ? 1 : 0;
    }
    return written;
}

void CanBusTransport::createDevice() {
    dropDevice();
    QString error;
    device_ = QCanBus::instance()->createDevice(settings_.plugin, settings_.interfaceName, &error);
    if (!device_)
        return connectionLost(tr("cannot create the device: %1").arg(error));
    device_->setParent(this);
    if (settings_.bitrate)
        device_->setConfigurationParameter(QCanBusDevice::BitRateKey, QVariant(*settings_.bitrate));
    watchDevice();
    if (!device_->connectDevice())
        connectionLost(tr("cannot connect: %1").arg(device_->errorString()));
}

void CanBusTransport::watchDevice() {
    connect(device_, &QCanBusDevice::stateChanged, this, &CanBusTransport::onDeviceState);
    connect(device_, &QCanBusDevice::errorOccurred, this, &CanBusTransport::onDeviceError);
    connect(device_, &QCanBusDevice::framesReceived, this, &CanBusTransport::onFramesReceived);
}

void CanBusTransport::onDeviceState(QCanBusDevice::CanBusDeviceState deviceState) {
    if (deviceState == QCanBusDevice::ConnectedState) {
        if (reconnector_.connected())
            countReconnect();
        setState(State::Connected);
    } else if (deviceState == QCanBusDevice::UnconnectedState) {
        connectionLost(tr("the interface went away"));
    }
}

// A failed connection or read means the interface is gone; other errors are passed on only.
void CanBusTransport::onDeviceError(QCanBusDevice::CanBusError error) {
    const QString message = device_->errorString();
    if (error == QCanBusDevice::ConnectionError || error == QCanBusDevice::ReadError)
        return connectionLost(message);
    if (error == QCanBusDevice::WriteError)
        return reportWriteFailure(true);
    emit problem(tr("%1: %2").arg(description(), message));
}

// Everything the device has now goes out as one batch; of the bus errors in it the first is reported.
void CanBusTransport::onFramesReceived() {
    std::vector<CanFrame> frames;
    std::size_t foreign = 0;
    QStringList busErrors;
    for (const QCanBusFrame& canBusFrame : device_->readAllFrames()) {
        if (canBusFrame.hasLocalEcho())
            continue;
        if (canBusFrame.frameType() == QCanBusFrame::ErrorFrame)
            busErrors.append(device_->interpretErrorFrame(canBusFrame));
        else if (const auto frame = fromCanBus(canBusFrame))
            frames.push_back(*frame);
        else
            ++foreign;
    }
    if (!busErrors.isEmpty())
        emit problem(tr("%1: bus error: %2 (%n error frame(s))", nullptr, int(busErrors.size()))
                         .arg(description(), busErrors.first()));
    countMalformed(foreign, tr("%n frame(s) that are not 29-bit data frames of up to 8 bytes; left out",
                               nullptr, int(foreign)));
    deliver(std::move(frames));
}

// Device errors and state changes report one loss several times: only the first schedules a retry.
void CanBusTransport::connectionLost(const QString& reason) {
    if (state() == State::Closed || reconnector_.isWaiting())
        return;
    dropDevice();
    const auto delay = reconnector_.lost();
    reportConnectionLost(reason, delay);
    setState(State::Reconnecting);
}

// The device may be in the middle of a signal: it is deleted later, and says nothing more until then.
void CanBusTransport::dropDevice() {
    if (!device_)
        return;
    device_->disconnect(this);
    if (device_->state() != QCanBusDevice::UnconnectedState)
        device_->disconnectDevice();
    device_->deleteLater();
    device_ = nullptr;
}

// Reports the first failed write of a run of failures, not each one.
void CanBusTransport::reportWriteFailure(bool failed) {
    if (failed && !writeFailing_) {
        const QString reason = device_->errorString();
        emit problem(tr("%1: cannot send: %2")
                         .arg(description(), reason.isEmpty() ? tr("the device refused the frame") : reason));
    }
    writeFailing_ = failed;
}

} // namespace stellwerk::transport
