#pragma once

#include "cs2/Header.h"
#include "cs2/Messages.h"
#include "station/AckKey.h"

#include <QObject>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

class QTimer;

namespace stellwerk::station {

// How long to wait for an acknowledgement and how often to send again (document 1.2.5: a command
// without acknowledgement must be assumed not carried out).
struct CommandPolicy {
    std::chrono::milliseconds timeout{250};
    int retries = 2; // sends after the first one
    // False for a request that one device on the bus may leave unanswered (status data of another
    // program on the bus): its silence says nothing about the connection to the station.
    bool silenceMeansTrouble = true;
};

// How a tracked command ended.
struct CommandResult {
    enum class Status : std::uint8_t {
        Acknowledged, // an answer with the same command and payload arrived
        Rejected,     // the answer says it was not carried out (see isRejection)
        TimedOut,     // no answer after every retry
        NotSent,      // the transport refused the frame
        Cancelled,    // withdrawn by the caller or the session closed
    };

    Status status = Status::TimedOut;
    std::optional<cs2::Message> answer;
    int attempts = 0;

    bool succeeded() const { return status == Status::Acknowledged; }
};

const char* commandStatusName(CommandResult::Status status);

using CommandId = std::uint64_t;
using CommandCallback = std::function<void(const CommandResult&)>;
// Puts frames of a command on the bus with our current hash, marked with the command's id so that they can
// be withdrawn while they still wait for the wire; false when the transport refused them.
using FrameSink = std::function<bool(std::span<const can::CanFrame>, CommandId)>;
// Takes back the frames of a command that have not reached the wire yet.
using FrameWithdrawal = std::function<void(CommandId)>;

// Keeps every command that waits for its acknowledgement: matches answers by AckKey (O(1) per frame),
// sends again on timeout and reports success or failure once. Several commands with the same key are
// answered in the order they were sent. A command that ends (answered, given up, cancelled, forgotten)
// has whatever of it still waits for the wire withdrawn, and a retry replaces the previous attempt's
// waiting frames instead of piling up behind them: nothing of a finished command reaches the station later.
class CommandTracker final : public QObject {
    Q_OBJECT

public:
    explicit CommandTracker(FrameSink sink, FrameWithdrawal withdraw = {}, QObject* parent = nullptr);
    ~CommandTracker() override;

    // Sends a command and waits for its answer. Returns 0 (and reports NotSent at once) when the message
    // has no one-to-one answer or the transport refused it.
    CommandId send(const cs2::Message& command, CommandCallback done, CommandPolicy policy = {});
    // Sends frames (a request with follow-up frames) answered by one acknowledgement with this key.
    CommandId sendFrames(std::vector<can::CanFrame> frames, AckKey key, CommandCallback done,
                         CommandPolicy policy = {});

    // Offers a received answer; completes the oldest command waiting for it. Returns true if it did.
    bool offer(const cs2::Message& answer);
    // Withdraws a command without reporting it (its callback is not called).
    void forget(CommandId id);
    // Ends every waiting command with Cancelled.
    void cancelAll();

    // Called when a command is given up (TimedOut), with the time of its first send: whoever knows
    // whether the station was heard since can decide that the connection is no longer to be trusted.
    using GiveUpObserver = std::function<void(std::chrono::steady_clock::time_point firstSent)>;
    void setGiveUpObserver(GiveUpObserver observer) { giveUpObserver_ = std::move(observer); }

    std::size_t pendingCount() const { return pending_.size(); }
    bool isPending(CommandId id) const { return pending_.count(id) != 0; }
    // Every retry sent so far, for the status bar and tests.
    std::uint64_t retriesSent() const { return retriesSent_; }

private:
    using Clock = std::chrono::steady_clock;
    using Deadlines = std::multimap<Clock::time_point, CommandId>;

    struct Pending {
        std::vector<can::CanFrame> frames;
        AckKey key;
        CommandCallback done;
        CommandPolicy policy;
        int attempts = 0;
        Clock::time_point firstSent;
        Deadlines::iterator deadline;
    };

    bool transmit(CommandId id, Pending& pending);
    void expire();
    void scheduleTimer();
    void finish(CommandId id, CommandResult::Status status, std::optional<cs2::Message> answer = {});
    void unlink(CommandId id, Pending& pending);

    void withdraw(CommandId id);

    FrameSink sink_;
    FrameWithdrawal withdraw_;
    GiveUpObserver giveUpObserver_;
    QTimer* timer_;
    CommandId nextId_ = 1;
    std::unordered_map<CommandId, Pending> pending_;
    std::unordered_map<AckKey, std::deque<CommandId>, AckKeyHash> byKey_;
    Deadlines deadlines_;
    std::uint64_t retriesSent_ = 0;
};

} // namespace stellwerk::station
