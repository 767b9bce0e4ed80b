#pragma once

#include "busreading/FrameClassifier.h"
#include "can/CanFrame.h"

#include <QObject>
#include <QString>
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace stellwerk::transport {
class Transport;
}

namespace stellwerk::bus {

// One CAN bus as the program holds it: the transport that reaches it (not owned), the protocols expected
// on it and a name for people ("CS2", "can1"). It sorts every batch it receives by protocol and hands each
// protocol's frames to the sessions that subscribed to it; frames no session takes are still counted
// (foreign ones included) and seen by the monitor, never dropped silently.
class Bus final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(Bus)

public:
    using Delivery = std::function<void(const std::vector<can::CanFrame>&)>;

    Bus(transport::Transport& transport, busreading::BusProfile profile, QString name = {},
        QObject* parent = nullptr);
    ~Bus() override;

    transport::Transport& transport() const { return transport_; }
    const busreading::BusProfile& profile() const { return profile_; }
    const QString& name() const { return name_; }

    // From now on the frames of `protocol` received on this bus go to `deliver`, a batch at a time and in
    // the order they came, until `subscriber` unsubscribes or is destroyed.
    void subscribe(busreading::Protocol protocol, QObject* subscriber, Delivery deliver);
    void unsubscribe(const QObject* subscriber);
    // Frames received since the bus was made that belong to `protocol` (Foreign: to none it expects).
    std::uint64_t received(busreading::Protocol protocol) const;

signals:
    // Every frame on the wire, for a monitor: one signal per batch the transport read (`outgoing` false)
    // and per block it wrote (`outgoing` true), in the order they passed.
    void framesSeen(const std::vector<stellwerk::can::CanFrame>& frames, bool outgoing);

private:
    struct Subscription {
        busreading::Protocol protocol;
        const QObject* subscriber;
        Delivery deliver;
    };

    void receive(const std::vector<can::CanFrame>& frames);
    bool subscribed(const QObject* subscriber) const;

    transport::Transport& transport_;
    busreading::BusProfile profile_;
    QString name_;
    std::vector<Subscription> subscriptions_;
    std::array<std::uint64_t, busreading::ProtocolCount> received_{};
};

} // namespace stellwerk::bus
