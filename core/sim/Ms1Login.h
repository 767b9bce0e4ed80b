#pragma once

#include "can/CanFrame.h"
#include "mcan/Messages.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::sim {

// The MS1's side of the M-CAN login (notes B§3.1, trace #3-#16). Stages 0-3 carry one byte of the UID
// each in the id and no data, so that two MS1s whose UIDs begin alike send identical frames and go on
// together until their bytes differ; the master echoes the byte, and a foreign byte means another MS1 won
// this stage: this one gives up and tries again later. Stages 4-7 follow back to back, then the master's
// grant names the node and the start handle.
class Ms1Login {
public:
    enum class Outcome : std::uint8_t {
        Ignored,   // not a frame of this login's current stage
        Advanced,  // our byte echoed: the next stage is in the outbox
        Lost,      // a foreign byte echoed: another MS1 logs in; try again later
        Granted,   // node and start handle given (grant())
        FlashMode, // granted with the flash bit: the MS1 goes into its boot loader
    };

    explicit Ms1Login(std::uint32_t uid) : uid_(uid) {}

    // Starts (again) at stage 0: the frame to send.
    can::CanFrame start();
    // Stops expecting anything (unplugged, lost, or logged in).
    void stop() { expecting_ = Expecting::Nothing; }
    bool running() const { return expecting_ != Expecting::Nothing; }

    // A master's login frame. Frames to send go to `out`.
    Outcome onReply(const mcan::LoginReply& reply, std::vector<can::CanFrame>& out);
    Outcome onGrant(const mcan::LoginGrant& grant);

    std::uint8_t stage() const { return stage_; }
    std::uint8_t mid() const { return mid_; }
    // Whether the master said in its stage-0 reply that it is a CS1, ECoS or CS2 (type 01), which asks for
    // the slave description; an MS1 master (00) does not (notes B§5.4 D2).
    bool masterWantsDescription() const { return masterType_ != 0; }
    const mcan::LoginGrant& grant() const { return grant_; }

private:
    enum class Expecting : std::uint8_t { Nothing, Reply, Grant };

    std::uint8_t uidByte(std::uint8_t stage) const { return std::uint8_t(uid_ >> (8 * (3 - stage))); }
    void sendDetails(std::vector<can::CanFrame>& out) const;

    std::uint32_t uid_;
    Expecting expecting_ = Expecting::Nothing;
    std::uint8_t stage_ = 0;
    std::uint8_t mid_ = 0;
    std::uint8_t masterType_ = 1;
    mcan::LoginGrant grant_;
};

} // namespace stellwerk::sim
