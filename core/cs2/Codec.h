#pragma once

#include "base/Expected.h"
#include "cs2/DecodeError.h"
#include "cs2/Header.h"
#include "cs2/Messages.h"

namespace stellwerk::cs2 {

using DecodeResult = Expected<Message, DecodeError>;

// Frame -> typed message. Pure, allocation-free; unknown commands decode as Unknown, malformed
// frames (DLC above 8, too short, a length no form has, reserved values) as a DecodeError.
DecodeResult decode(const CanFrame& frame);

// Typed message -> frame with exactly the documented bytes (unused data bytes zero).
CanFrame encode(const Message& message);

} // namespace stellwerk::cs2
