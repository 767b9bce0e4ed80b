#pragma once

#include "mcan/Messages.h"
#include "sim/Ms1Keys.h"
#include "sim/Ms1Memory.h"
#include "sim/Ms1Upgrade.h"

namespace stellwerk::sim {

// What an MS1 does with the frames its master sends of its own accord (notes B§3.2-3.8): it answers the
// master's questions (stack size, its name, the master's poll), and shows what the master pushes: stop and
// go, a short circuit, the speed and functions of a locomotive on its stack, locomotives added to or deleted
// from the stack, a new name for itself or a locomotive, and the answers to its take requests.
class Ms1MasterFrames {
public:
    Ms1MasterFrames(Ms1Identity& identity, Ms1Memory& memory, Ms1Upgrade& upgrade, Ms1Keys& keys)
        : identity_(identity), memory_(memory), upgrade_(upgrade), keys_(keys) {}

    // False when the message is none of these (the MS1 then ignores it).
    bool take(const mcan::Message& message, Ms1Outbox& out);

private:
    template <typename Other>
    bool on(const Other&, Ms1Outbox&) {
        return false;
    }
    bool on(const mcan::StackSizeRequest& request, Ms1Outbox& out);
    bool on(const mcan::NameRequest& request, Ms1Outbox& out);
    bool on(const mcan::MasterPoll& poll, Ms1Outbox& out);
    bool on(const mcan::StatusValue& status, Ms1Outbox& out);
    bool on(const mcan::FunctionValue& value, Ms1Outbox& out);
    bool on(const mcan::StackAdd& add, Ms1Outbox& out);
    bool on(const mcan::StackDelete& deletion, Ms1Outbox& out);
    bool on(const mcan::NameSegment& segment, Ms1Outbox& out);
    bool on(const mcan::Throttle& throttle, Ms1Outbox& out);
    void throttleOfShown(std::uint16_t state, Ms1Outbox& out);

    Ms1Identity& identity_;
    Ms1Memory& memory_;
    Ms1Upgrade& upgrade_;
    Ms1Keys& keys_;
};

} // namespace stellwerk::sim
