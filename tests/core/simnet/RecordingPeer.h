#pragma once

#include "can/CanFrame.h"

#include <QObject>
#include <vector>

namespace stellwerk::sim::test {

// A device on a simulated bus that keeps what it receives and sends what a test tells it to.
class RecordingPeer : public QObject {
    Q_OBJECT

public:
    void receive(const can::CanFrame& frame) { received.push_back(frame); }
    void send(const std::vector<can::CanFrame>& frames) { emit framesEmitted(frames); }

    std::vector<can::CanFrame> received;

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);
};

} // namespace stellwerk::sim::test
