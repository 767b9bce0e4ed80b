#include "mcan/HandleRoles.h"

#include <type_traits>

namespace stellwerk::mcan {

Message HandleRoles::decode(const can::CanFrame& frame) const {
    return mcan::decode(frame, roleOf(frame));
}

Message HandleRoles::observe(const can::CanFrame& frame) {
    Message message = decode(frame);
    learn(message, frame);
    return message;
}

HandleRole HandleRoles::roleOf(const can::CanFrame& frame) const {
    if (!isMcan(frame) || layoutOf(frame.id) != Layout::Session)
        return HandleRole::Unknown;
    const SessionId s = readSession(frame.id);
    return role(slaveNodeOf(s.node), s.handle);
}

HandleRole HandleRoles::role(std::uint8_t slaveNode, std::uint16_t handle) const {
    const auto known = handles_.find({slaveNodeOf(slaveNode), handle});
    return known == handles_.end() ? HandleRole::Unknown : known->second.role;
}

std::string HandleRoles::name(std::uint8_t slaveNode, std::uint16_t handle) const {
    const auto known = handles_.find({slaveNodeOf(slaveNode), handle});
    return known == handles_.end() ? std::string() : known->second.name;
}

std::string HandleRoles::slaveName(std::uint8_t slaveNode) const {
    for (const auto& [key, handle] : handles_)
        if (key.first == slaveNodeOf(slaveNode) && handle.role == HandleRole::SlaveDescription)
            return handle.name;
    return {};
}

void HandleRoles::set(std::uint8_t slaveNode, std::uint16_t handle, HandleRole role) {
    if (handles_.size() >= MaximumHandles && !handles_.contains({slaveNode, handle}))
        return;
    Handle& known = handles_[{slaveNode, handle}];
    if (known.role != role)
        known = Handle{role, {}};
}

void HandleRoles::forgetPair(std::uint8_t slaveNode) {
    std::erase_if(handles_, [slaveNode](const auto& entry) { return entry.first.first == slaveNode; });
}

// A name arrives four characters at a time; the slave's own name comes from the slave, a locomotive's from
// the master.
void HandleRoles::addName(std::uint8_t slaveNode, const NameSegment& segment) {
    const auto known = handles_.find({slaveNode, segment.at.handle});
    if (known == handles_.end() || segment.offset > 12 || segment.offset % 4 != 0)
        return;
    const bool slaveSent = isSlaveNode(segment.at.node);
    const HandleRole role = known->second.role;
    if (!(role == HandleRole::Loco && !slaveSent) && !(role == HandleRole::SlaveDescription && slaveSent))
        return;
    std::string& name = known->second.name;
    if (segment.offset == 0)
        name.clear();
    if (name.size() != segment.offset)
        return; // a segment out of order: keep what was read
    for (std::uint8_t i = 0; i < segment.count; ++i) {
        if (segment.chars[i] == '\0')
            return;
        name += segment.chars[i];
    }
}

void HandleRoles::learn(const Message& message, const can::CanFrame& frame) {
    const std::uint8_t pair = slaveNodeOf(std::uint8_t(frame.id & 0x7F));
    std::visit(
        [&](const auto& m) {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, LoginGrant>) {
                forgetPair(slaveNodeOf(m.node));
                set(slaveNodeOf(m.node), m.startHandle, HandleRole::Start);
            } else if constexpr (std::is_same_v<T, Poll>) {
                set(pair, m.at.handle, HandleRole::Poll);
            } else if constexpr (std::is_same_v<T, SdHandleAnswer>) {
                set(pair, m.sdHandle, HandleRole::SlaveDescription);
            } else if constexpr (std::is_same_v<T, SyHandleAnswer>) {
                set(pair, m.syHandle, HandleRole::SystemStatus);
            } else if constexpr (std::is_same_v<T, LocoListAnswer>) {
                set(pair, m.next, HandleRole::Loco);
            } else if constexpr (std::is_same_v<T, StackAdd>) {
                set(pair, m.locoHandle, HandleRole::Loco);
            } else if constexpr (std::is_same_v<T, NameSegment>) {
                addName(pair, m);
            }
        },
        message);
}

} // namespace stellwerk::mcan
