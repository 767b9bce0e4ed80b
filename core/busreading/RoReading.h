#pragma once

#include "busreading/FrameDescription.h"

#include <memory>

namespace stellwerk::busreading {

// An RO frame read by the RO codec's report, the way the module's ids on this bus say it goes (request
// or answer). Used by FrameDescription only.
std::shared_ptr<const FrameReading> roReading(const can::CanFrame& frame, const BusProfile& profile);

} // namespace stellwerk::busreading
