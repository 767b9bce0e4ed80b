#pragma once

#include "mcan/Messages.h"
#include "mcanhandhelds/Handheld.h"
#include "mcanhandhelds/HandheldRailway.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace stellwerk::mcanhandhelds {

class SlaveSession;

// What a handheld's session asks of its master: the railway's facts, and the decisions that concern more
// than one handheld (who holds a locomotive) or the railway (driving, stop and go).
class SessionHost {
public:
    virtual ~SessionHost() = default;
    virtual const HandheldLoco* loco(std::uint32_t locId) const = 0;
    virtual LocoDrive drive(std::uint32_t locId) const = 0;
    virtual bool stopped() const = 0;
    virtual bool shortCircuit() const = 0;
    // The handheld asks for a locomotive: true when it may drive it now.
    virtual bool take(SlaveSession& session, std::uint32_t locId) = 0;
    virtual void release(SlaveSession& session, std::uint32_t locId) = 0;
    // Whether somebody other than this handheld holds the locomotive.
    virtual bool heldByOther(const SlaveSession& session, std::uint32_t locId) const = 0;
    // The handheld drives: function 1 is speed and direction (the value byte), function n is f(n-2).
    virtual void drive(SlaveSession& session, std::uint32_t locId, std::uint8_t function,
                       std::uint8_t value) = 0;
    virtual void stopKey(SlaveSession& session, bool stop) = 0;
    // Something shown of the handheld changed (name, state, its locomotive, ...).
    virtual void changed(SlaveSession& session) = 0;
};

// The master's side of the conversation with one logged-in MS1 (notes B§3.2 to B§3.8): its handles, its
// locomotive stack, and an answer to every request it makes, in whatever order it asks (the MS1 runs several
// query "threads" at once). The handles are the ECoS's (poll 1, start 2, SY 3, SD 8, locomotives from 9).
class SlaveSession {
public:
    static constexpr std::uint16_t PollHandle = 0x0001;
    static constexpr std::uint16_t StartHandle = 0x0002;
    static constexpr std::uint16_t SyHandle = 0x0003;
    static constexpr std::uint16_t SdHandle = 0x0008;
    static constexpr std::uint16_t FirstLocoHandle = 0x0009;

    SlaveSession(Handheld handheld, std::uint32_t masterUid, SessionHost& host);

    const Handheld& handheld() const { return handheld_; }
    Handheld& handheld() { return handheld_; }
    std::uint8_t slaveNode() const { return handheld_.slaveNode; }
    std::uint8_t masterNode() const { return handheld_.masterNode(); }

    // Answers a frame from this handheld; `understood` is false for a request on a handle nobody issued or
    // one that does not fit the handle (counted by the master, never answered).
    std::vector<mcan::Message> answer(const mcan::Message& message, bool& understood);

    // What the master tells the handheld of its own accord.
    std::vector<mcan::Message> status(bool stopped, bool shortCircuit) const;
    // The locomotive's speed, direction and functions where the handheld shows it and they changed.
    std::vector<mcan::Message> driveChanged(std::uint32_t locId, const LocoDrive& drive);
    // Locomotive `locId` is held by someone else now (true) or free again (false).
    std::vector<mcan::Message> holderChanged(std::uint32_t locId, bool heldByOther);
    std::vector<mcan::Message> setStack(const std::vector<std::uint32_t>& stack);
    std::vector<mcan::Message> rename(const std::string& name) const;
    // The frame before the stage-7 reply (trace #15) and the master poll of a silent handheld (7.2.2).
    mcan::Message announce() const;
    mcan::Message masterPoll() const;
    // Gives up every locomotive it holds (the session ends).
    void releaseAll();

private:
    mcan::Address from(std::uint16_t handle, std::uint8_t priority = mcan::prio::Data) const {
        return {priority, handle, masterNode()};
    }
    std::optional<std::uint32_t> locoOf(std::uint16_t handle) const;
    std::optional<std::uint16_t> handleOf(std::uint32_t locId) const;
    std::uint16_t addLoco(std::uint32_t locId);

    std::vector<mcan::Message> answerStart(const mcan::Message& message, bool& understood);
    std::vector<mcan::Message> answerSlaveDescription(const mcan::Message& message, bool& understood);
    std::vector<mcan::Message> answerSystemStatus(const mcan::Message& message, bool& understood);
    std::vector<mcan::Message> answerLoco(const mcan::Message& message, std::uint16_t handle,
                                          std::uint32_t locId, bool& understood);
    std::vector<mcan::Message> answerLocoProperty(const mcan::LocoQuery& query, std::uint32_t locId) const;
    std::vector<mcan::Message> answerFunction(const mcan::FunctionQuery& query, std::uint32_t locId) const;
    std::vector<mcan::Message> answerThrottle(const mcan::Throttle& request, std::uint32_t locId);
    std::vector<mcan::Message> answerName(const mcan::NameRequest& request, std::uint32_t locId) const;
    std::vector<mcan::Message> nextInStack(const mcan::LocoListQuery& query) const;
    void learnName(const mcan::NameSegment& segment);
    std::uint8_t functionValue(std::uint8_t function, std::uint32_t locId) const;
    void rememberShown(std::uint32_t locId);

    Handheld handheld_;
    std::uint32_t masterUid_;
    SessionHost& host_;
    std::vector<std::pair<std::uint16_t, std::uint32_t>> locoHandles_; // the stack, in order
    std::uint16_t nextHandle_ = FirstLocoHandle;
    std::vector<std::pair<std::uint8_t, std::uint8_t>> shown_; // function, value last told of its locomotive
    std::string nameRead_; // the handheld's name as it sends it, segment by segment
};

} // namespace stellwerk::mcanhandhelds
