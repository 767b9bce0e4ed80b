#pragma once

#include "SimOptions.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedOrcDevices.h"

#include <QTimer>
#include <memory>
#include <vector>

namespace stellwerk::simapp {

// The OpenRailCAN devices stellwerk-sim puts on the station's bus (--orc-booster, --orc-decoders,
// --orc-encoders), with the clocks that make them do something on their own: the booster's overload comes
// and goes, an input of each encoder changes. What they do is printed, so that a user sees the other side of
// `stellwerk-cli orc find|switch|watch`; a throttle drives one loco now and then, for a central that
// forwards it to the station.
class SimOrcDevices {
public:
    static constexpr std::uint32_t BoosterUid = 0x3A2E0300;
    static constexpr std::uint32_t FirstDecoderUid = 0x3A2E0101;
    static constexpr std::uint32_t FirstEncoderUid = 0x3A2E0201;
    static constexpr std::uint32_t ThrottleUid = 0x3A2E0400;

    SimOrcDevices(sim::SimulatedBus& bus, const SimOptions& options);

    // Powers them up (each announces itself) and starts the clocks.
    void plugIn();
    bool empty() const { return !booster_ && decoders_.empty() && encoders_.empty() && !throttle_; }

private:
    void toggleOverload();
    void toggleInputs();
    void driveNow();

    SimOptions options_;
    std::unique_ptr<sim::SimulatedOrcBooster> booster_;
    std::vector<std::unique_ptr<sim::SimulatedOrcDecoder>> decoders_;
    std::vector<std::unique_ptr<sim::SimulatedOrcEncoder>> encoders_;
    std::unique_ptr<sim::SimulatedOrcThrottle> throttle_;
    QTimer overloadClock_;
    QTimer inputClock_;
    QTimer throttleClock_;
    int nextSpeed_ = 0;
    bool overloaded_ = false;
    int nextInput_ = 0;
};

} // namespace stellwerk::simapp
