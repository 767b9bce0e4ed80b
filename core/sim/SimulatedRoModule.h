#pragma once

#include "can/CanFrame.h"
#include "ro/Codec.h"
#include "ro/RegisterFile.h"
#include "ro/RoProfile.h"

#include <QObject>
#include <chrono>
#include <optional>
#include <vector>

namespace stellwerk::sim {

// An RO relay/IO module on the CAN bus (seed 004), for tests, stellwerk-sim and the demo: a 64 KiB register
// file with relays and inputs where its profile puts them, answering requests on its ids as the document
// and the notes' decisions say (R6 bit access, R13 no wrap, R21 0xFE before the job check). It remembers
// the last job id and answers a repeat with 0xFD. Faults can be injected: requests or answers lost, answers
// late, the module unplugged. Like the other simulated devices it is a peer behind a transport: frames come
// in through receive(), its answers go out through framesEmitted.
class SimulatedRoModule : public QObject {
    Q_OBJECT

public:
    // One request the module carried out, in order: what Stellwerk's writes really did to the relays.
    struct Write {
        std::uint16_t address = 0;
        ro::Width width = ro::Width::Byte;
        std::uint32_t value = 0;
        std::uint8_t job = 0;
    };

    explicit SimulatedRoModule(ro::RoProfile profile, QObject* parent = nullptr);

    // A frame from the bus (any sender); only requests on the module's request id are read.
    void receive(const can::CanFrame& frame);

    const ro::RoProfile& profile() const { return profile_; }
    const ro::RegisterFile& registers() const { return registers_; }
    // Relays and inputs numbered from 1, as the document numbers relays (004 §3.4).
    bool relay(int number) const;
    std::uint32_t relays() const;
    // The relays as someone left them before (not a request: not in writes()).
    void presetRelays(std::uint32_t relays);
    bool input(int number) const;
    // Sets an input and, when it changed, its change flag (read-to-clear, 004 §2.1).
    void setInput(int number, bool on);
    const std::vector<Write>& writes() const { return writes_; }
    std::optional<std::uint8_t> lastJob() const { return lastJob_; }
    // As if another master had just used this job id.
    void rememberJob(std::uint8_t job) { lastJob_ = job; }

    // Faults: the next `count` requests never reach the module; the next `count` answers never leave it
    // (the request is carried out); answers leave after `delay`; an unplugged module is silent.
    void loseRequests(int count) { requestsToLose_ = count; }
    void loseAnswers(int count) { answersToLose_ = count; }
    void setAnswerDelay(std::chrono::milliseconds delay) { answerDelay_ = delay; }
    // Every nth answer is lost (0: none), for stellwerk-sim.
    void loseEveryAnswer(int n) { loseEvery_ = n; }
    void unplug() { plugged_ = false; }
    void plugIn() { plugged_ = true; }
    bool pluggedIn() const { return plugged_; }
    // Notes R10: add a read's data to 0xFD (off by default: DLC 2).
    void setDuplicateCarriesData(bool on) { duplicateCarriesData_ = on; }

    // Requests seen, answers sent, requests lost to injected faults.
    std::uint64_t requestsSeen() const { return requestsSeen_; }
    std::uint64_t answersSent() const { return answersSent_; }

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);
    // A relay word was written (by a request): the relays as they are now.
    void relaysChanged(std::uint32_t relays);

private:
    ro::Answer carryOut(std::span<const std::uint8_t> payload);
    ro::Answer execute(const ro::Request& request);
    std::optional<std::uint32_t> readRegister(const ro::Request& request);
    void answer(const ro::Answer& answer);
    void clearChangeFlags(const ro::Request& read);

    ro::RoProfile profile_;
    ro::RegisterFile registers_;
    std::vector<Write> writes_;
    std::optional<std::uint8_t> lastJob_;
    int requestsToLose_ = 0;
    int answersToLose_ = 0;
    int loseEvery_ = 0;
    std::uint64_t answersMade_ = 0;
    std::chrono::milliseconds answerDelay_{0};
    bool plugged_ = true;
    bool duplicateCarriesData_ = false;
    std::uint64_t requestsSeen_ = 0;
    std::uint64_t answersSent_ = 0;
};

} // namespace stellwerk::sim
