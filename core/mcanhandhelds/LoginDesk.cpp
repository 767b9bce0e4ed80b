#include "mcanhandhelds/LoginDesk.h"

namespace stellwerk::mcanhandhelds {
namespace {

constexpr std::uint8_t MaximumMid = 31;

// The data of the master's replies to stages 1-3: the ECoS's, which the trace shows working (notes D2).
constexpr std::array<std::array<std::uint8_t, 8>, 3> ReplyData = {{
    {0x00, 0x00, 0x00, 0x97, 0x00, 0x00, 0x01, 0x03},
    {0x01, 0x13, 0x00, 0x05, 0x00, 0x00, 0x00, 0x00},
    {0x00, 0x00, 0x00, 0x01, 0x03, 0x00, 0x00, 0x01},
}};

} // namespace

LoginDesk::LoginDesk(std::uint32_t masterUid, std::chrono::milliseconds stageTimeout)
    : masterUid_(masterUid), stageTimeout_(stageTimeout) {}

std::optional<std::uint8_t> LoginDesk::freeMid() const {
    for (std::uint8_t mid = 1; mid <= MaximumMid; ++mid)
        if (!logins_.contains(mid))
            return mid;
    return std::nullopt;
}

std::uint32_t LoginDesk::uidOf(const std::array<std::uint8_t, 4>& bytes) {
    return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 | std::uint32_t(bytes[2]) << 8 |
           bytes[3];
}

mcan::LoginReply LoginDesk::reply(std::uint8_t stage, std::uint8_t uidByte, std::uint8_t mid) const {
    mcan::LoginReply reply{stage, uidByte, mid, {}};
    if (stage == 0) // our UID and the type "CS/E master" (00 01 00 01), after which an MS1 reads its SD
        reply.data = {std::uint8_t(masterUid_ >> 24),
                      std::uint8_t(masterUid_ >> 16),
                      std::uint8_t(masterUid_ >> 8),
                      std::uint8_t(masterUid_),
                      0x00,
                      0x01,
                      0x00,
                      0x01};
    else
        reply.data = ReplyData[stage - 1];
    return reply;
}

LoginDesk::Outcome LoginDesk::receive(const mcan::LoginRequest& request, Clock::time_point now) {
    Outcome outcome;
    if (request.stage == 0) {
        const std::optional<std::uint8_t> mid = freeMid();
        if (!mid) {
            outcome.unexpected = true; // 31 logins at once: this one waits for its next try
            return outcome;
        }
        Login& login = logins_[*mid];
        login.uidBytes[0] = request.uidByte;
        login.last = now;
        outcome.replies.push_back(reply(0, request.uidByte, *mid));
        return outcome;
    }
    const auto found = logins_.find(request.mid);
    // A stage that is not the next one: another slave lost the arbitration on the same MID, or a frame was
    // lost. The UID byte of the login under way stays; the other slave sees it echoed and tries again later.
    if (found == logins_.end() || found->second.stage != request.stage - 1) {
        outcome.unexpected = true;
        return outcome;
    }
    found->second.uidBytes[request.stage] = request.uidByte;
    found->second.stage = request.stage;
    found->second.last = now;
    outcome.replies.push_back(reply(request.stage, request.uidByte, request.mid));
    return outcome;
}

LoginDesk::Outcome LoginDesk::receive(const mcan::LoginDetails& details, Clock::time_point now) {
    Outcome outcome;
    const auto found = logins_.find(details.mid);
    if (found == logins_.end() || found->second.stage < 3 || details.stage < 4) {
        outcome.unexpected = true;
        return outcome;
    }
    Login& login = found->second;
    login.detailSeen[details.stage - 4] = true;
    login.details[details.stage - 4] = details.data;
    login.last = now;
    if (!login.detailSeen[0] || !login.detailSeen[3])
        return outcome; // the grant answers stage 7, once the UID of stage 4 is known
    const std::array<std::uint8_t, 4> stated{login.details[0][0], login.details[0][1], login.details[0][2],
                                             login.details[0][3]};
    if (stated != login.uidBytes) { // the UID of stage 4 is not the one of stages 0-3: start again
        logins_.erase(found);
        outcome.unexpected = true;
        return outcome;
    }
    outcome.completed = CompletedLogin{details.mid, uidOf(login.uidBytes), login.details};
    logins_.erase(found);
    return outcome;
}

void LoginDesk::expire(Clock::time_point now) {
    std::erase_if(logins_, [&](const auto& entry) { return now - entry.second.last > stageTimeout_; });
}

std::vector<LoginDesk::Pending> LoginDesk::pending() const {
    std::vector<Pending> list;
    for (const auto& [mid, login] : logins_)
        list.push_back({mid, login.stage, login.uidBytes});
    return list;
}

} // namespace stellwerk::mcanhandhelds
