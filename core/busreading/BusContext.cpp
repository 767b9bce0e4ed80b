#include "busreading/BusContext.h"

#include "busreading/McanReading.h"
#include "mcan/HandleRoles.h"

#include <variant>

namespace stellwerk::busreading {

BusContext::BusContext() : roles_(std::make_unique<mcan::HandleRoles>()) {}
BusContext::~BusContext() = default;
BusContext::BusContext(BusContext&&) noexcept = default;
BusContext& BusContext::operator=(BusContext&&) noexcept = default;

// Only M-CAN frames reveal handles; a CS2 frame without the hash marker must not pass for one (B§6.2).
// A handheld's name changes with a name segment, and is gone with a new login of its pair.
void BusContext::observe(const can::CanFrame& frame) {
    if (!mcan::isMcan(frame))
        return;
    const mcan::Message message = roles_->observe(frame);
    if (!std::holds_alternative<mcan::NameSegment>(message) &&
        !std::holds_alternative<mcan::LoginGrant>(message))
        return;
    if (const auto node = handheldNodeOf(frame, message))
        names_[*node / 2] = roles_->slaveName(*node);
}

FrameDescription BusContext::read(const can::CanFrame& frame, const BusProfile& profile) {
    observe(frame);
    return FrameDescription(frame, profile, this);
}

void BusContext::clear() {
    *roles_ = mcan::HandleRoles();
    names_ = {};
}

std::string BusContext::handheldName(std::uint8_t slaveNode) const {
    return slaveNode / 2 < names_.size() ? names_[slaveNode / 2] : std::string();
}

} // namespace stellwerk::busreading
