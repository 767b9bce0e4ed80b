#pragma once

#include "can/CanFrame.h"

#include <QObject>
#include <QTimer>
#include <functional>
#include <vector>

namespace stellwerk::sim {

// One CAN bus shared by simulated devices (the CS2, MS1 handhelds) and the outside (the station server's
// listeners), as the real bus is: a frame one peer sends reaches every other peer and the outside, never
// its sender. Frames travel in rounds, one per turn of the event loop, and what peers answer goes out in
// the next round, so that devices started together really speak at once. Within a round the frames go as
// CAN arbitration lets them: the lowest identifier among the senders' next frames first, each sender's
// frames in its own order; and identical frames of two peers pass as one (the M-CAN login relies on both:
// two MS1s whose UIDs begin alike go on together until their bytes differ, and the lower byte wins).
class SimulatedBus : public QObject {
    Q_OBJECT

public:
    explicit SimulatedBus(QObject* parent = nullptr);
    ~SimulatedBus() override;

    // Puts a peer on the bus: what it emits (framesEmitted) goes onto the bus, and it receives (receive())
    // what the others put there. A peer that is destroyed leaves the bus.
    template <typename Peer>
    void attach(Peer& peer) {
        add(peer, [&peer](const can::CanFrame& frame) { peer.receive(frame); });
        connect(&peer, &Peer::framesEmitted, this,
                [this, sender = &peer](const std::vector<can::CanFrame>& frames) { put(frames, sender); });
    }
    void detach(QObject& peer);
    std::size_t peerCount() const { return peers_.size(); }

    // Frames from the outside (a client of the server): every peer receives them in the next round.
    void putFromOutside(const std::vector<can::CanFrame>& frames);

signals:
    // The frames the peers put on the bus in one round, in bus order, for the outside.
    void framesCarried(const std::vector<stellwerk::can::CanFrame>& frames);

private:
    struct Peer {
        QObject* object = nullptr;
        std::function<void(const can::CanFrame&)> receive;
    };
    // A frame waiting for its round, and who sent it (one peer, several for a merged frame; none: outside).
    struct Pending {
        can::CanFrame frame;
        std::vector<const QObject*> senders;
    };

    void add(QObject& peer, std::function<void(const can::CanFrame&)> receive);
    void put(const std::vector<can::CanFrame>& frames, const QObject* sender);
    bool mergeIntoRound(const can::CanFrame& frame, const QObject* sender);
    void deliverRound();
    static std::vector<Pending> arbitrate(std::vector<Pending> round);
    bool attached(const QObject* object) const;

    std::vector<Peer> peers_;
    std::vector<Pending> round_;
    QTimer roundClock_;
};

} // namespace stellwerk::sim
