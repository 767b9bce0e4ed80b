#pragma once

#include "can/CanFrame.h"
#include "can/ReportFields.h"
#include "mcan/Codec.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::mcan {

class HandleRoles;

// One field of a message as people and scripts read it (shared with the other protocols' reports).
using Field = can::Field;
using FieldFormat = can::FieldFormat;

// Every field of a message, the id's first (sender, node, handle, priority; or stage, UID byte and MID).
std::vector<Field> describe(const Message& message);

// A name of 4-character segments as it is shown: printable ASCII kept, any other byte as \xNN, so that a
// device on the bus cannot put control characters into a terminal or a table.
std::string printable(std::string_view bytes);

// An M-CAN frame written for people and for scripts, one line each. With HandleRoles it names what the
// frame's handle is ("object=loco loco=\"003 131-0\"") and tells status from function frames.
class FrameReport {
public:
    explicit FrameReport(const can::CanFrame& frame, const HandleRoles* roles = nullptr);

    const Message& message() const { return message_; }
    std::string_view name() const { return nameOf(message_); }
    bool decoded() const { return !std::holds_alternative<Unknown>(message_); }
    // "key=value ..." of the fields (an unknown frame: its id fields and why it is not understood).
    std::string detailText() const;
    // "1800252B 2 01 01  mcan.function-query  from=slave node=43 ..."
    std::string text() const;
    // {"id":"1800252B","dlc":2,"data":"0101","name":"mcan.function-query","fields":{...}}
    std::string json() const;
    std::optional<std::uint64_t> number(std::string_view key) const;

private:
    can::CanFrame frame_;
    Message message_;
    std::vector<Field> fields_;
};

} // namespace stellwerk::mcan
