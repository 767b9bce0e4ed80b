#pragma once

#include "can/CanFrame.h"
#include "ro/Codec.h"
#include "ro/RoProfile.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace stellwerk::ro {

// One field of an RO message as people and scripts read it: addresses, job ids and data in hex, the
// access width as a word.
struct Field {
    enum class Format : std::uint8_t { Hex, Text };
    std::string_view key;
    std::uint32_t number = 0;
    Format format = Format::Hex;
    unsigned digits = 2;
    std::string_view text; // Text fields only
};

// The fields of a request (width, address, job, and a write's value) or an answer.
std::vector<Field> describe(const Request& request);
std::vector<Field> describe(const Answer& answer);

// An RO frame written for people and for scripts, one line each. The direction comes from the module's
// ids (the only thing that tells an RO frame, notes B7); a payload that is no RO message reads as
// "ro.unknown" with the reason.
class FrameReport {
public:
    FrameReport(const can::CanFrame& frame, Direction direction);

    Direction direction() const { return direction_; }
    bool decoded() const { return !std::holds_alternative<DecodeError>(message_); }
    // "ro.write-word", "ro.ok", ...; "ro.unknown" for a payload that did not decode.
    std::string_view name() const;
    // "direction=request address=0x0000 job=0x35 width=word value=0x2000", or why it did not decode.
    std::string detailText() const;
    // "01FE0001 8 13 00 00 35 00 20 00 00  ro.write-word  direction=request ..."
    std::string text() const;
    // {"id":"01FE0001","extended":true,"dlc":8,"data":"...","name":"ro.write-word","direction":"request",
    //  "fields":{...}} (an unknown one: "error" and "byte" instead of "fields")
    std::string json() const;
    std::optional<std::uint64_t> number(std::string_view key) const;

    const Request* request() const { return std::get_if<Request>(&message_); }
    const Answer* answer() const { return std::get_if<Answer>(&message_); }

private:
    can::CanFrame frame_;
    Direction direction_;
    std::variant<Request, Answer, DecodeError> message_;
    std::vector<Field> fields_;
};

// Every RO message name, for choosing one in a filter.
std::vector<std::string_view> messageNames();

} // namespace stellwerk::ro
