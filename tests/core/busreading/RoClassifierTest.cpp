// RO frames on a bus shared with the CS2 and MS1 handhelds (notes B7, C4): only the ids configured for a
// module claim a frame for RO, standard or extended, asked before the other protocols.

#include "busreading/FrameClassifier.h"
#include "busreading/FrameDescription.h"

#include <gtest/gtest.h>

namespace stellwerk::busreading::test {
namespace {

using can::CanFrame;

const std::uint8_t Go[] = {0x00, 0x00, 0x47, 0x11, 0x01};
const std::uint8_t RelayWrite[] = {0x13, 0x00, 0x00, 0x35, 0x00, 0x20, 0x00, 0x00}; // 004 §3.4
const std::uint8_t RelayOk[] = {0x01, 0x00, 0x35, 0x00, 0x00, 0x00, 0x00};          // Derived (B4.4)
const std::uint8_t Poll[] = {0x00, 0x00, 0x00, 0x2A};

// A station's bus with two RO modules: the simulator's 29-bit module 1 and an 11-bit one at 0x700/0x701.
BusProfile sharedBus() {
    BusProfile profile = BusProfile::centralStation();
    profile.addRoModule(ro::RoProfile::simulator(1).ids);
    profile.addRoModule(ro::FrameIds{0x700, 0x701, false});
    return profile;
}

TEST(RoClassifier, CS2McanRoAndForeignFramesOnOneBus) {
    struct Row {
        const char* what;
        CanFrame frame;
        Protocol protocol;
    };
    const Row table[] = {
        {"CS2 go (003 §1.2)", CanFrame::extendedFrame(0x00004711, Go), Protocol::Cs2},
        {"CS2 hash-marked", CanFrame::extendedFrame(0x0C084B11, Go), Protocol::Cs2},
        {"M-CAN poll (trace #82)", CanFrame::extendedFrame(0x0C0007AB, Poll), Protocol::Mcan},
        {"M-CAN login stage 0", CanFrame::extendedFrame(0x1C00007E, {}), Protocol::Mcan},
        {"RO request, module 1", CanFrame::extendedFrame(0x01FE0001, RelayWrite), Protocol::Ro},
        {"RO answer, module 1", CanFrame::extendedFrame(0x01FF0001, RelayOk), Protocol::Ro},
        {"RO request, 11-bit module", CanFrame::standard(0x700, RelayWrite), Protocol::Ro},
        {"RO answer, 11-bit module", CanFrame::standard(0x701, RelayOk), Protocol::Ro},
        {"RO payload on an unconfigured id", CanFrame::extendedFrame(0x01FE0002, RelayWrite), Protocol::Cs2},
        {"the 11-bit module's id as a 29-bit frame", CanFrame::extendedFrame(0x700, RelayWrite),
         Protocol::Cs2},
        {"module 1's id as an 11-bit frame", CanFrame::standard(0x001, RelayWrite), Protocol::Foreign},
        {"another program's 11-bit frame", CanFrame::standard(0x123, Go), Protocol::Foreign},
    };
    const BusProfile profile = sharedBus();
    for (const Row& row : table)
        EXPECT_EQ(protocolName(classify(row.frame, profile)), protocolName(row.protocol)) << row.what;
}

TEST(RoClassifier, ConfiguredIdsAreAskedFirst) {
    // A CS2-looking 29-bit id configured for an RO module belongs to the module (notes C4).
    BusProfile profile = BusProfile::centralStation();
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x00004711, RelayWrite), profile), Protocol::Cs2);
    profile.addRoModule(ro::FrameIds{0x00004711, 0x00004712, true});
    EXPECT_EQ(profile.protocols().front(), Protocol::Ro);
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x00004711, RelayWrite), profile), Protocol::Ro);
    EXPECT_EQ(protocolName(Protocol::Ro), "ro");
}

TEST(RoClassifier, TheModuleAndDirectionComeFromTheIds) {
    const BusProfile profile = sharedBus();
    const auto answer = profile.roFrame(CanFrame::standard(0x701, RelayOk));
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->module, 1u);
    EXPECT_EQ(answer->direction, ro::Direction::Answer);
    const auto request = profile.roFrame(CanFrame::extendedFrame(0x01FE0001, RelayWrite));
    ASSERT_TRUE(request);
    EXPECT_EQ(request->module, 0u);
    EXPECT_EQ(request->direction, ro::Direction::Request);
}

TEST(RoClassifier, RoFramesAreDescribedByTheRoCodec) {
    const BusProfile profile = sharedBus();
    const FrameDescription request(CanFrame::extendedFrame(0x01FE0001, RelayWrite), profile);
    EXPECT_EQ(request.protocolName(), "ro");
    EXPECT_EQ(request.name(), "ro.write-word");
    EXPECT_FALSE(request.isResponse());
    EXPECT_EQ(request.number("value"), 0x2000u);

    const FrameDescription answer(CanFrame::standard(0x701, RelayOk), profile);
    EXPECT_TRUE(answer.isResponse());
    EXPECT_EQ(answer.text(),
              "701 7 01 00 35 00 00 00 00  ro.ok  direction=answer width=none job=0x35 value=0x00000000");
    EXPECT_EQ(answer.json().substr(0, 49), "{\"protocol\":\"ro\",\"module\":1,\"id\":\"701\",\"extended\"");

    const std::uint8_t junk[] = {0x30};
    const FrameDescription unknown(CanFrame::standard(0x700, junk), profile);
    EXPECT_FALSE(unknown.decoded());
    EXPECT_EQ(unknown.name(), "ro.unknown");

    const auto names = messageNames(profile);
    EXPECT_NE(std::find(names.begin(), names.end(), "ro.write-word"), names.end());
}

} // namespace
} // namespace stellwerk::busreading::test
