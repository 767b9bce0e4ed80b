#pragma once

#include "can/CanFrame.h"
#include "mcan/Messages.h"

namespace stellwerk::mcan {

// What an object handle stands for between one master and its slave (document 6.3.1): a decoder learns it
// from the answers that hand the handle out (HandleRoles), since status and function frames have the same
// shape and only the handle tells them apart.
enum class HandleRole : std::uint8_t { Unknown, Start, Poll, SlaveDescription, SystemStatus, Loco };

std::string_view roleName(HandleRole role);

// Whether the frame belongs to M-CAN on a bus shared with the CS2 protocol (Id.h isMcanId): 29-bit only.
bool isMcan(const can::CanFrame& frame);

// Frame -> typed message. Pure and allocation-free; never fails: a frame no documented form fits decodes
// as Unknown with the reason. `role` is what the frame's handle is known to be; without it, list frames
// (cmd 010) read as a locomotive's functions unless they carry the status priority 100.
Message decode(const can::CanFrame& frame, HandleRole role = HandleRole::Unknown);

// Typed message -> frame; decode(encode(m)) gives m back, and encode(decode(f)) gives f back.
can::CanFrame encode(const Message& message);

// Whether the sender of a session frame is a master (even node) or a slave (odd node below 126).
bool fromMaster(const can::CanFrame& frame);

} // namespace stellwerk::mcan
