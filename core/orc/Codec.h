#pragma once

#include "can/CanFrame.h"
#include "orc/Messages.h"

namespace stellwerk::orc {

// Whether a frame is in OpenRailCAN space (OrcId.h isOrcId): 29-bit only.
bool isOrc(const can::CanFrame& frame);

// Frame -> typed message. Pure and allocation-free; never fails: a frame no documented form fits decodes as
// Unknown with the reason (wrong length, wrong direction, unknown group or sub-command, priority 00).
Message decode(const can::CanFrame& frame);

// Typed message -> frame; decode(encode(m)) gives m back (with m's priority filled in), and
// encode(decode(f)) gives f back.
can::CanFrame encode(const Message& message);

// The priority a message is sent with when its Origin says 0 (notes A1.4).
std::uint8_t defaultPriority(const Message& message);

// The identifier fields of a message (its sender, group and direction) as they go on the wire.
Header headerOf(const Message& message);

} // namespace stellwerk::orc
