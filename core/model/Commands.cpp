#include "model/Commands.h"

#include "cs2/Request.h"

namespace stellwerk::model::commands {

cs2::Message speed(cs2::LocId loco, std::uint16_t speed) {
    return cs2::request(cs2::LocoSpeed{loco, speed});
}

cs2::Message direction(cs2::LocId loco, cs2::Direction direction) {
    return cs2::request(cs2::LocoDirection{loco, std::uint8_t(direction)});
}

cs2::Message function(cs2::LocId loco, std::uint8_t function, bool on) {
    return cs2::request(cs2::LocoFunction{loco, function, std::uint8_t(on), std::nullopt});
}

cs2::Message emergencyStop(cs2::LocId loco) {
    return cs2::request(cs2::LocoEmergencyStop{loco});
}

cs2::Message stop() {
    return cs2::request(cs2::SystemStop{0});
}

cs2::Message go() {
    return cs2::request(cs2::SystemGo{0});
}

cs2::Message switchOutput(cs2::LocId article, std::uint8_t output, std::optional<std::uint16_t> time10ms) {
    return cs2::request(cs2::AccessorySwitch{article, output, 1, time10ms});
}

cs2::Message readChannel(std::uint32_t device, std::uint8_t channel) {
    return cs2::request(cs2::SystemStatus{device, channel, std::nullopt, std::nullopt});
}

cs2::Message writeChannel(std::uint32_t device, std::uint8_t channel, std::uint16_t value) {
    return cs2::request(cs2::SystemStatus{device, channel, value, std::nullopt});
}

cs2::Message readCv(cs2::LocId decoder, cs2::CvAddress cv) {
    return cs2::request(cs2::ConfigRead{decoder, cv, std::uint8_t(1), std::nullopt});
}

cs2::Message writeCv(cs2::LocId decoder, cs2::CvAddress cv, std::uint8_t value, bool mainTrack,
                     cs2::DccProgrammingMode mode) {
    const auto control =
        std::uint8_t((mainTrack ? cs2::ConfigWrite::MainTrack : 0) | (std::uint8_t(mode) << 4));
    return cs2::request(cs2::ConfigWrite{decoder, cv, value, control});
}

cs2::Message discoverMfx(std::uint8_t range) {
    return cs2::request(cs2::LocoDiscovery{std::nullopt, range, std::nullopt});
}

cs2::Message bindMfx(std::uint32_t mfxUid, std::uint16_t sid) {
    return cs2::request(cs2::MfxBind{mfxUid, sid});
}

cs2::Message verifyMfx(std::uint32_t mfxUid, std::uint16_t sid) {
    return cs2::request(cs2::MfxVerify{mfxUid, sid, std::nullopt});
}

cs2::Message requestMemoryFunction(std::uint16_t device, std::uint16_t function, bool activate) {
    return cs2::request(
        cs2::AutomationSwitch{device, function, std::uint8_t(activate ? 1 : 0), 0, std::nullopt});
}

cs2::Message announceAutomationState(std::uint16_t device, std::uint16_t function, std::uint8_t state) {
    return cs2::announcement(cs2::AutomationSwitch{device, function, state, 0, std::nullopt});
}

} // namespace stellwerk::model::commands
