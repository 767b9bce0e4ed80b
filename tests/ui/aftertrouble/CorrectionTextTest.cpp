// Issue 32: what Stellwerk brought back after trouble is said in one sentence a person understands: whose,
// what had failed, and what was done (or that nothing was, because it brings nothing into motion).

#include "aftertrouble/CorrectionText.h"

#include <gtest/gtest.h>

namespace stellwerk::ui {
namespace {

using model::CommandTarget;
using model::Correction;

TEST(CorrectionText, ALocomotiveStoppedAfterItsFailedSpeedWasCarriedOutLate) {
    const Correction correction{CommandTarget::speed(0x4001), 200, 0, true};
    EXPECT_EQ(CorrectionText::of(correction, nullptr),
              "MFX 1: the station carried out a command late that had failed (speed 20 %); stopped.");
}

TEST(CorrectionText, ARunningLocomotiveSetBackToItsConfirmedSpeed) {
    const Correction correction{CommandTarget::speed(0x4001), 700, 300, false};
    EXPECT_EQ(CorrectionText::of(correction, nullptr),
              "MFX 1: a command that had failed (speed 70 %) could still reach the station; set back to "
              "speed 30 %.");
}

TEST(CorrectionText, ALateSlowerSpeedThatStays) {
    const Correction correction{CommandTarget::speed(0x4001), 100, std::nullopt, true};
    EXPECT_EQ(CorrectionText::of(correction, nullptr),
              "MFX 1: the station carried out a command late that had failed (speed 10 %); it stays, as it "
              "brings nothing into motion.");
}

TEST(CorrectionText, TrackPowerAccessoriesAndFunctions) {
    EXPECT_EQ(CorrectionText::of({CommandTarget::power(), 1, 0, false}, nullptr),
              "Track power: a command that had failed (on) could still reach the station; set back to off.");
    EXPECT_EQ(CorrectionText::of({CommandTarget::accessory(5), 1, 0, true}, nullptr),
              "Accessory 5: the station carried out a command late that had failed (position 1); set back to "
              "position 0.");
    EXPECT_EQ(CorrectionText::of({CommandTarget::function(0x4001, 3), 1, 0, true}, nullptr),
              "MFX 1: the station carried out a command late that had failed (F3 on); set back to F3 off.");
}

} // namespace
} // namespace stellwerk::ui
