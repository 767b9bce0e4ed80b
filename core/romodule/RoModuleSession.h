#pragma once

#include "ro/Exchange.h"
#include "ro/RoProfile.h"

#include <QObject>
#include <QString>
#include <QTimer>
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>

namespace stellwerk::bus {
class Bus;
}

namespace stellwerk::romodule {

// The timing of one module's conversation; the document gives none (notes R19), these are the notes'.
struct SessionTiming {
    std::chrono::milliseconds answerTimeout{100};
    std::chrono::milliseconds pollPeriod{250}; // inputs at 4 Hz; at most 10 Hz is sensible (notes B3.3)
    ro::Exchange::Limits limits{};
    // The first job id; by default a random one, since the module's memory from before is unknown.
    std::optional<std::uint8_t> firstJob;
};

// What happened on the conversation, for the Devices panel and for tests.
struct SessionCounters {
    std::uint64_t ok = 0;          // requests that ended well
    std::uint64_t duplicates = 0;  // 0xFD answers with our job id
    std::uint64_t invalid = 0;     // 0xFE answers to our requests
    std::uint64_t timeouts = 0;    // answers waited for in vain
    std::uint64_t stale = 0;       // answers with another job id (late, or another master's)
    std::uint64_t unsolicited = 0; // answers while nothing was in flight
    std::uint64_t malformed = 0;   // frames on the answer id that are no RO answer
    std::uint64_t flagsLost = 0;   // reads sent again after a lost answer: change flags may be lost
};

// Stellwerk's side of one RO relay/IO module: it drives the module stop-and-wait over a bus (one request
// in flight, answers matched by job id, ro::Exchange's retry rules), reads the relays on start into a
// shadow that only the module's OK changes, switches relays by writing the whole output word from that
// shadow, polls the inputs and their change flags, and marks the module offline when it stops answering
// and online again when it answers. It never reports a relay switched that the module did not confirm.
class RoModuleSession final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RoModuleSession)

public:
    enum class State { Starting, Online, Offline };
    Q_ENUM(State)
    using RequestId = std::uint64_t;

    // The bus's profile must list the module's ids (busreading::BusProfile::addRoModule); see problem().
    RoModuleSession(bus::Bus& bus, ro::RoProfile profile, SessionTiming timing = {},
                    QObject* parent = nullptr);
    ~RoModuleSession() override;

    // Why the session cannot work on this bus: an unusable profile, ids the bus profile does not list, or
    // 11-bit frames on a UDP/TCP gateway (whose 13-byte form has no room for them). Empty when it can.
    QString problem() const;
    // Reads the relays and starts polling the inputs; does nothing when problem() is not empty.
    void start();
    void stop();

    // Relays numbered from 1 (004 §3.4). False, and nothing sent, while the module is offline or for a
    // relay the profile does not have. The change reaches outputs() only when the module confirmed it.
    bool setOutput(int number, bool on);
    bool switchAllOff();
    // A register access of the register explorer (also without start()); requestFinished tells how it
    // went.
    RequestId read(std::uint16_t address, ro::Width width);
    RequestId write(std::uint16_t address, ro::Width width, std::uint32_t value);

    State state() const { return state_; }
    // Nothing in flight and nothing waiting.
    bool idle() const { return !current_ && queue_.empty(); }
    // The relays as the module confirmed them (bit n-1 = relay n); nullopt until read.
    std::optional<std::uint32_t> outputs() const { return shadow_; }
    std::optional<std::uint32_t> inputs() const { return inputs_; }
    const SessionCounters& counters() const { return counters_; }
    const ro::RoProfile& profile() const { return profile_; }
    std::uint8_t nextJob() const { return nextJob_; }

signals:
    void stateChanged(stellwerk::romodule::RoModuleSession::State state);
    // The relays as the module confirmed them.
    void outputsChanged(std::uint32_t outputs);
    // The inputs, and those whose change flag was set since the last poll.
    void inputsChanged(std::uint32_t inputs, std::uint32_t changed);
    // Relay changes the module did not confirm (bits of `relays`), and why.
    void outputsFailed(std::uint32_t relays, const QString& why);
    void requestFinished(stellwerk::romodule::RoModuleSession::RequestId id,
                         const stellwerk::ro::Outcome& outcome);

private:
    enum class Purpose : std::uint8_t { ReadOutputs, Poll, WriteOutputs, User };
    struct Job {
        Purpose purpose = Purpose::User;
        ro::Request request;
        RequestId id = 0;
    };

    void receive(const std::vector<can::CanFrame>& frames);
    void answered(const ro::Answer& answer);
    void timedOut();
    void follow(const ro::Step& step);
    void transmit();
    void sendNext();
    void finish(const ro::Outcome& outcome);
    void readOutputs(std::uint32_t value);
    void finishOutputs(const ro::Outcome& outcome);
    void finishPoll(std::uint32_t value);
    void goOffline();
    void setState(State state);
    void enqueue(Purpose purpose, ro::Request request = {}, RequestId id = 0);
    bool queued(Purpose purpose) const;
    void poll();
    bool changeOutputs(std::uint32_t mask, std::uint32_t values);
    std::uint32_t outputMask() const;
    std::uint8_t takeJob() { return nextJob_++; }

    bus::Bus& bus_;
    ro::RoProfile profile_;
    SessionTiming timing_;
    State state_ = State::Starting;
    bool running_ = false; // started: relays read, inputs polled
    bool stopped_ = false; // stop(): nothing more goes out
    std::deque<Job> queue_;
    std::optional<Job> current_;
    std::optional<ro::Exchange> exchange_;
    QTimer answerTimer_;
    QTimer pollTimer_;
    std::uint8_t nextJob_ = 0;
    RequestId lastRequestId_ = 0;
    std::optional<std::uint32_t> shadow_;
    std::optional<std::uint32_t> inputs_;
    std::uint32_t pendingMask_ = 0; // relays to change, not yet sent
    std::uint32_t pendingValues_ = 0;
    std::uint32_t writingMask_ = 0;  // relays the write in flight changes
    std::uint32_t writingValue_ = 0; // the whole word it writes
    SessionCounters counters_;
};

} // namespace stellwerk::romodule
