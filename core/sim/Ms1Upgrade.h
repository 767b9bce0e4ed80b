#pragma once

#include "can/CanFrame.h"
#include "mcan/Messages.h"
#include "sim/Ms1LocoInquiry.h"
#include "sim/Ms1Memory.h"

#include <cstdint>
#include <deque>
#include <optional>

namespace stellwerk::sim {

// The upgrade (Aufrüstung) as the MS1 drives it after its login (notes B§3.2, trace #17-#81): it asks for
// its SD handle, then its SY handle, the status list (type, then value, per index until the end echo) and
// the loco-stack lists 0x80, 0x81 and 0x82; each locomotive the 0x80 list names is inquired about
// (Ms1LocoInquiry) beside the lists, one after the other, as the trace interleaves them. A locomotive the
// master adds later is inquired about the same way (document 7.7.2).
class Ms1Upgrade {
public:
    explicit Ms1Upgrade(Ms1Memory& memory) : memory_(memory) {}

    // Starts with the SD handle, or with the SY handle when the master wants no slave description.
    void start(bool askSlaveDescription, Ms1Outbox& out);
    // Forgets every open question (a new login, unplugged).
    void reset();
    // A frame from the master: true when it answered an open question (the next ones are in `out`).
    bool take(const can::CanFrame& frame, const mcan::Message& message, Ms1Outbox& out);
    // Asks about a locomotive the master added to the stack.
    void inquire(std::uint16_t handle, Ms1Outbox& out);
    // Whether every question has been answered.
    bool done() const { return step_ == Step::Done && !inquiry_ && waiting_.empty(); }

private:
    enum class Step : std::uint8_t { Idle, SdHandle, SyHandle, StatusType, StatusValue, LocoList, Done };

    void ask(Step step, const mcan::Message& question, Ms1Outbox& out);
    void afterHandle(const mcan::Message& message, Ms1Outbox& out);
    void afterStatus(const mcan::Message& message, Ms1Outbox& out);
    void afterList(const mcan::Message& message, Ms1Outbox& out);
    void askList(std::uint8_t list, std::uint16_t previous, Ms1Outbox& out);
    void addLoco(std::uint16_t handle, Ms1Outbox& out);
    bool takeInquiry(const can::CanFrame& frame, const mcan::Message& message, Ms1Outbox& out);
    void nextInquiry(Ms1Outbox& out);

    Ms1Memory& memory_;
    Step step_ = Step::Idle;
    std::uint8_t index_ = 0; // status index, or loco-stack list (0x80, 0x81, 0x82)
    std::optional<can::CanFrame> asked_;
    std::optional<Ms1LocoInquiry> inquiry_;
    std::deque<std::uint16_t> waiting_; // locomotives still to inquire about
};

} // namespace stellwerk::sim
