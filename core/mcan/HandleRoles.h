#pragma once

#include "can/CanFrame.h"
#include "mcan/Codec.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>

namespace stellwerk::mcan {

// What the frames on a bus have revealed so far about each master/slave pair: which handle is the start,
// poll, slave-description, system-status or a locomotive's, and the names sent for the slave and its
// locomotives. A monitor feeds it every frame in bus order (observe) and reads frames with it (decode), so
// that status and function frames, which have the same shape, are told apart, and a locomotive's handle is
// shown with its name. A new login of a pair forgets what was known of it.
class HandleRoles {
public:
    // Decodes the frame with what is known of its handle.
    Message decode(const can::CanFrame& frame) const;
    // Learns from a frame (decoding it); returns the message as decode() gives it.
    Message observe(const can::CanFrame& frame);

    HandleRole roleOf(const can::CanFrame& frame) const;
    HandleRole role(std::uint8_t slaveNode, std::uint16_t handle) const;
    // The name sent for a locomotive handle, or for the slave (its SD handle); empty when none was seen.
    std::string name(std::uint8_t slaveNode, std::uint16_t handle) const;
    std::string slaveName(std::uint8_t slaveNode) const;
    // How many handles are known (for tests and memory bounds).
    std::size_t size() const { return handles_.size(); }

private:
    struct Handle {
        HandleRole role = HandleRole::Unknown;
        std::string name; // up to 16 characters, as sent
    };
    using Key = std::pair<std::uint8_t, std::uint16_t>; // slave node, handle

    static std::uint8_t slaveNodeOf(std::uint8_t node) { return std::uint8_t(node | 1); }
    void learn(const Message& message, const can::CanFrame& frame);
    void set(std::uint8_t slaveNode, std::uint16_t handle, HandleRole role);
    void forgetPair(std::uint8_t slaveNode);
    void addName(std::uint8_t slaveNode, const NameSegment& segment);

    static constexpr std::size_t MaximumHandles = 4096; // a bus of garbage cannot grow it without bound
    std::map<Key, Handle> handles_;
};

} // namespace stellwerk::mcan
