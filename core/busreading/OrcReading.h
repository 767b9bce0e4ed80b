#pragma once

#include "busreading/FrameDescription.h"

#include <memory>

namespace stellwerk::busreading {

// An OpenRailCAN frame read by the ORC codec's report. Used by FrameDescription only.
std::shared_ptr<const FrameReading> orcReading(const can::CanFrame& frame);

} // namespace stellwerk::busreading
