#pragma once

#include "cs2/LocId.h"
#include "cs2/Messages.h"

#include <cstdint>
#include <optional>

// What the railway asks of the station, one named builder per intent, so that the model never spells
// wire-header fields (priority, response bit, hash) or message layouts; the session stamps the hash.
namespace stellwerk::model::commands {

// Locomotives (document 2.4, 3.4-3.6).
cs2::Message speed(cs2::LocId loco, std::uint16_t speed);
cs2::Message direction(cs2::LocId loco, cs2::Direction direction);
cs2::Message function(cs2::LocId loco, std::uint8_t function, bool on);
cs2::Message emergencyStop(cs2::LocId loco);

// Track power on every station (2.1, 2.2).
cs2::Message stop();
cs2::Message go();

// Switch one accessory output on; the station switches it off after `time10ms`, or after its default
// time when there is none (4.1).
cs2::Message switchOutput(cs2::LocId article, std::uint8_t output,
                          std::optional<std::uint16_t> time10ms = {});

// A device's status-data channel: read its value, or set a configuration value (2.12).
cs2::Message readChannel(std::uint32_t device, std::uint8_t channel);
cs2::Message writeChannel(std::uint32_t device, std::uint8_t channel, std::uint16_t value);

// Decoder programming: read one CV byte (3.7), write one CV on the main or the programming track in a
// DCC mode (3.8).
cs2::Message readCv(cs2::LocId decoder, cs2::CvAddress cv);
cs2::Message writeCv(cs2::LocId decoder, cs2::CvAddress cv, std::uint8_t value, bool mainTrack,
                     cs2::DccProgrammingMode mode);

// mfx registration: a whole discovery cycle over `range` (3.1), bind a decoder to a SID (3.2), check that
// it answers under that SID (3.3).
cs2::Message discoverMfx(std::uint8_t range);
cs2::Message bindMfx(std::uint32_t mfxUid, std::uint16_t sid);
cs2::Message verifyMfx(std::uint32_t mfxUid, std::uint16_t sid);

// Automation (9.1): ask a device to run (activate) or release a memory function; say a block's state on
// the bus as a status answer on its address.
cs2::Message requestMemoryFunction(std::uint16_t device, std::uint16_t function, bool activate);
cs2::Message announceAutomationState(std::uint16_t device, std::uint16_t function, std::uint8_t state);

} // namespace stellwerk::model::commands
