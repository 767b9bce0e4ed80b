#pragma once

#include "can/CanFrame.h"

#include <QObject>
#include <cstdint>
#include <string>
#include <vector>

namespace stellwerk::sim::test {

// Who sent a frame of the chapter-11 trace: the MS1 (login dir 0, node 43), the ECoS as its master (login
// dir 1, node 42), or another device of the ECoS's bus (E-CAN frames, #1, #2, #58, #96-#98).
enum class TraceSender : std::uint8_t { Slave, Master, Other };
TraceSender senderOf(const can::CanFrame& frame);

// The ECoS of the chapter-11 trace as a peer on a simulated bus (notes B§4.2 test use (d)): it sends the
// trace's master frames, and the frames of the other devices, in the trace's order, each as soon as the MS1
// has sent every slave frame the trace shows before it. The MS1's frames count as a multiset, so that it may
// interleave its query threads differently (B§3: answers are keyed by request, not by order); a frame the
// trace's MS1 never sent is kept in `unexpected`.
class TraceMaster : public QObject {
    Q_OBJECT

public:
    explicit TraceMaster(std::vector<can::CanFrame> trace);

    // Sends what precedes the first slave frame (#1, #2).
    void start();
    void receive(const can::CanFrame& frame);

    bool finished() const { return next_ == trace_.size(); }
    // What the master waits for: "#14 1C03B07E 8 00 00 40 10 01 08 00 10", or "" when finished.
    std::string waitingFor() const;
    const std::vector<can::CanFrame>& unexpected() const { return unexpected_; }

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);

private:
    void sendReady();

    std::vector<can::CanFrame> trace_;
    std::vector<bool> heard_; // per slave frame of the trace: the MS1 sent it
    std::size_t next_ = 0;    // the next trace frame to send (or to wait for)
    std::vector<can::CanFrame> unexpected_;
};

} // namespace stellwerk::sim::test
