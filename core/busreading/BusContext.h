#pragma once

#include "busreading/FrameDescription.h"
#include "can/CanFrame.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>

namespace stellwerk::mcan {
class HandleRoles;
}

namespace stellwerk::busreading {

// What the frames of one bus have revealed so far that a single frame does not say: which M-CAN handle
// is a handheld's locomotive, system status or description, and the names sent for them. Status and
// function frames of an MS1 have the same shape, and only a handle learnt earlier tells them apart, so
// whatever shows frames (monitor, decoder, CLI) keeps one per bus, feeds it every frame in the order the
// bus carried them, and describes frames with it. Bounded, whatever the bus carries.
class BusContext {
public:
    BusContext();
    ~BusContext();
    BusContext(BusContext&&) noexcept;
    BusContext& operator=(BusContext&&) noexcept;

    // Learns from a frame; frames of other protocols teach nothing.
    void observe(const can::CanFrame& frame);
    // Learns from the frame, then describes it with all that is known (its own news included).
    FrameDescription read(const can::CanFrame& frame, const BusProfile& profile);
    // Forgets all that was learnt (a new capture, another source of frames).
    void clear();
    // The name the MS1 of the pair with this slave node sent, empty until it did (or after it logged in
    // again and before it sent it again).
    std::string handheldName(std::uint8_t slaveNode) const;

    // For the readings of core/busreading.
    const mcan::HandleRoles& handleRoles() const { return *roles_; }

private:
    std::unique_ptr<mcan::HandleRoles> roles_;
    std::array<std::string, 64> names_; // by slave node / 2 (1, 3, ... 125), kept for filtering many rows
};

} // namespace stellwerk::busreading
