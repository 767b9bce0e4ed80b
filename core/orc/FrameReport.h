#pragma once

#include "can/CanFrame.h"
#include "can/ReportFields.h"
#include "orc/Codec.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::orc {

// One field of a message as people and scripts read it (shared with the other protocols' reports).
using Field = can::Field;
using FieldFormat = can::FieldFormat;

// Every field of a message, the identifier's first (priority, sender type and bus id, direction).
std::vector<Field> describe(const Message& message);

// The device type's name: "system", "loco", "can-decoder", "can-encoder", "legacy-decoder", ...
std::string_view deviceTypeName(std::uint8_t type);

// An OpenRailCAN frame written for people and for scripts, one line each, in the shape of the M-CAN
// report: the frame, the message name, then key=value fields (an extension says so: extension=true).
class FrameReport {
public:
    explicit FrameReport(const can::CanFrame& frame);

    const Message& message() const { return message_; }
    std::string_view name() const { return nameOf(message_); }
    bool decoded() const { return !std::holds_alternative<Unknown>(message_); }
    // "key=value ..." of the fields (an unknown frame: its id fields and why it is not understood).
    std::string detailText() const;
    // "11100000 4 03 30 05 01  orc.decoder.switch  prio=2 type=system sender=0x0000 ..."
    std::string text() const;
    // {"id":"11100000","dlc":4,"data":"03300501","name":"orc.decoder.switch","fields":{...}}
    std::string json() const;
    std::optional<std::uint64_t> number(std::string_view key) const;

private:
    can::CanFrame frame_;
    Message message_;
    std::vector<Field> fields_;
};

} // namespace stellwerk::orc
