#include "TraceMaster.h"

#include "can/FrameText.h"
#include "mcan/Codec.h"

namespace stellwerk::sim::test {

namespace {

constexpr std::uint8_t TraceMasterNode = 42;
constexpr std::uint8_t TraceSlaveNode = 43;

} // namespace

TraceSender senderOf(const can::CanFrame& frame) {
    if (!mcan::isMcan(frame))
        return TraceSender::Other;
    if (mcan::layoutOf(frame.id) == mcan::Layout::Login)
        return mcan::readLogin(frame.id).fromMaster ? TraceSender::Master : TraceSender::Slave;
    const std::uint8_t node = mcan::readSession(frame.id).node;
    if (node == TraceSlaveNode)
        return TraceSender::Slave;
    return node == TraceMasterNode ? TraceSender::Master : TraceSender::Other;
}

TraceMaster::TraceMaster(std::vector<can::CanFrame> trace)
    : trace_(std::move(trace)), heard_(trace_.size(), false) {}

void TraceMaster::start() {
    sendReady();
}

void TraceMaster::receive(const can::CanFrame& frame) {
    bool matched = false;
    for (std::size_t i = 0; i < trace_.size() && !matched; ++i)
        if (!heard_[i] && senderOf(trace_[i]) == TraceSender::Slave && trace_[i] == frame)
            matched = heard_[i] = true;
    if (!matched)
        unexpected_.push_back(frame);
    sendReady();
}

std::string TraceMaster::waitingFor() const {
    if (finished())
        return {};
    return "#" + std::to_string(next_ + 1) + " " + can::formatDocument(trace_[next_]);
}

// Everything up to the next slave frame not heard yet goes out, in one emission per frame.
void TraceMaster::sendReady() {
    while (next_ < trace_.size()) {
        if (senderOf(trace_[next_]) == TraceSender::Slave) {
            if (!heard_[next_])
                return;
        } else {
            emit framesEmitted({trace_[next_]});
        }
        ++next_;
    }
}

} // namespace stellwerk::sim::test
