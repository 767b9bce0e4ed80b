#pragma once

#include "busreading/FrameDescription.h"
#include "mcan/Messages.h"

#include <cstdint>
#include <memory>
#include <optional>

namespace stellwerk::busreading {

class BusContext;

// An M-CAN frame read by the M-CAN codec's report; with a context, its handle is named ("object=loco
// loco=\"003 131-0\"") and status frames are told from function frames. Used by FrameDescription only.
std::shared_ptr<const FrameReading> mcanReading(const can::CanFrame& frame, const BusContext* context);

// The slave node of the pair an M-CAN frame belongs to: its sender's pair for a session frame, the node
// handed out for a login grant. Other login frames (no node yet), flash frames and the bus-busy frame
// belong to none.
std::optional<std::uint8_t> handheldNodeOf(const can::CanFrame& frame, const mcan::Message& message);

} // namespace stellwerk::busreading
