#pragma once

#include "mcan/Messages.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::mcanhandhelds {

// A login that went through all eight stages: the slave's UID and what it told of itself.
struct CompletedLogin {
    std::uint8_t mid = 0;
    std::uint32_t uid = 0;
    std::array<std::array<std::uint8_t, 8>, 4> details{}; // stages 4..7
};

// The master's side of the login (Anmeldung, document 6.2; notes B§3.1): several logins at once, each known
// by the MID handed out in the stage-0 reply; each stage's UID byte echoed, the stage-4 UID checked against
// the four bytes of stages 0-3, a login that stalls for `stageTimeout` forgotten. It answers and never
// decides a node: the master does that when a login completes.
class LoginDesk {
public:
    using Clock = std::chrono::steady_clock;

    LoginDesk(std::uint32_t masterUid, std::chrono::milliseconds stageTimeout);

    struct Outcome {
        std::vector<mcan::Message> replies;
        std::optional<CompletedLogin> completed;
        // The frame did not fit any login under way (a stage out of order, an unknown MID, a UID that did
        // not match): answered not at all, counted by the master.
        bool unexpected = false;
    };
    Outcome receive(const mcan::LoginRequest& request, Clock::time_point now);
    Outcome receive(const mcan::LoginDetails& details, Clock::time_point now);
    // Forgets logins whose next stage is overdue.
    void expire(Clock::time_point now);

    // A login under way, for display: the UID bytes read so far and the last stage answered.
    struct Pending {
        std::uint8_t mid = 0;
        int stage = 0;
        std::array<std::uint8_t, 4> uidBytes{};
    };
    std::vector<Pending> pending() const;

private:
    struct Login {
        int stage = 0; // the last stage of 0..3 answered; 4.. details
        std::array<std::uint8_t, 4> uidBytes{};
        std::array<bool, 4> detailSeen{};
        std::array<std::array<std::uint8_t, 8>, 4> details{};
        Clock::time_point last;
    };

    std::optional<std::uint8_t> freeMid() const;
    mcan::LoginReply reply(std::uint8_t stage, std::uint8_t uidByte, std::uint8_t mid) const;
    static std::uint32_t uidOf(const std::array<std::uint8_t, 4>& bytes);

    std::uint32_t masterUid_;
    std::chrono::milliseconds stageTimeout_;
    std::map<std::uint8_t, Login> logins_; // by MID
};

} // namespace stellwerk::mcanhandhelds
