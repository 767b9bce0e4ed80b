#pragma once

#include "can/CanFrame.h"
#include "mcan/Messages.h"
#include "sim/Ms1Memory.h"

#include <cstdint>
#include <optional>

namespace stellwerk::sim {

// Whether `answer` answers `question`: the master answers on the same handle and cmd by echoing the
// question's bytes and appending its answer; a bare echo ends a list (notes B§0 item 5).
bool echoes(const can::CanFrame& question, const can::CanFrame& answer);

// What an MS1 asks about one locomotive of its stack, one question at a time (notes B§3.2 step 6, trace
// #48-#81): its type, rail format 0 and 1, the functions (FKT 1 to 9: the description, then the value,
// until the end echo), the three `01 02 n 00`, `40 04`, the assignment, and the name until a NUL.
class Ms1LocoInquiry {
public:
    Ms1LocoInquiry(const Ms1Link& link, std::uint16_t handle) : link_(link), handle_(handle) {}

    std::uint16_t handle() const { return handle_; }
    // The first question.
    can::CanFrame start();
    // Whether the frame answers the open question.
    bool answeredBy(const can::CanFrame& frame) const { return asked_ && echoes(*asked_, frame); }
    // Learns from the answer; the next question, or nothing when everything is known.
    std::optional<can::CanFrame> answer(const mcan::Message& message, Ms1Loco& loco);

private:
    enum class Step : std::uint8_t {
        Type,
        Format,
        FormatDetail,
        Description,
        Value,
        Extra,
        Unknown4004,
        Assignment,
        Name,
        Done,
    };
    static constexpr std::uint8_t LastFunction = 9; // FKT 9 = f7: an MS1 shows eight functions

    std::optional<can::CanFrame> ask(Step step, std::uint8_t n = 0);
    can::CanFrame question() const;
    std::optional<can::CanFrame> afterProperty(const mcan::Message& message, Ms1Loco& loco);
    std::optional<can::CanFrame> afterFunction(const mcan::Message& message, Ms1Loco& loco);
    std::optional<can::CanFrame> afterName(const mcan::Message& message, Ms1Loco& loco);

    const Ms1Link& link_;
    std::uint16_t handle_;
    Step step_ = Step::Type;
    std::uint8_t n_ = 0; // function number, `01 02 n 00` counter or name offset
    std::optional<can::CanFrame> asked_;
};

} // namespace stellwerk::sim
