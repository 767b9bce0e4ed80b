// Every OpenRailCAN message (notes A2 #1-#42 and Stellwerk's extensions) encodes to a frame that decodes back
// to the same message, and that frame encodes back to the same bytes.

#include "orc/Codec.h"
#include "orc/FrameReport.h"
#include "orc/MessageBuilder.h"

#include <gtest/gtest.h>
#include <set>

using namespace stellwerk;
using namespace stellwerk::orc;

namespace {

constexpr Origin CentralOrigin{prio::Control, 0, 0x0000};
constexpr Origin Booster{prio::Safety, 0, 0x0042};
constexpr Origin Decoder{prio::Control, 2, 0x2E01};
constexpr Origin Encoder{prio::Control, 3, 0x2E02};
constexpr Origin Manager{prio::Management, 0, 0x0000};
constexpr Origin Device{prio::Management, 2, 0x2E01};

// One message of every kind and form, from the side that sends it.
std::vector<Message> samples() {
    return {
        AllOff{Booster, Target::all()},
        AllOff{Booster, Target::busId(0x2E01)},
        AllOff{Booster, Target::uid(0x3A2E2E01)},
        AllOn{Booster, Target::all()},
        AllOn{Booster, Target::busId(0x2E01)},
        AllOn{Booster, Target::uid(0x3A2E2E01)},
        Overload{Booster, false, 2, false, 0},
        Overload{Booster, true, 1, true, 3},
        LocoStop{CentralOrigin, Target::all()},
        LocoStop{CentralOrigin, Target::busId(0x0048)},
        LocoStop{CentralOrigin, Target::uid(0x3A2E0001)},
        LocoSpeedQuery{CentralOrigin, 0x0048},
        LocoSpeed{CentralOrigin, false, 0x0048, 0x8000 | 250},
        LocoSpeed{Booster, true, 0x0048, 500},
        LocoSpeedQueryByUid{CentralOrigin, 0x3A2E0001},
        LocoSpeedByUid{CentralOrigin, false, 0x3A2E0001, 1000, false},
        LocoSpeedByUid{CentralOrigin, false, 0x3A2E0001, 10, true},
        LocoSpeedByUid{Booster, true, 0x3A2E0001, 10, false},
        LocoFunctionsQuery{CentralOrigin, 0x0048},
        LocoFunctions{CentralOrigin, false, 0x0048, 0x80000001},
        LocoFunctions{Booster, true, 0x0048, 0x00000003},
        LocoFunctionQuery{CentralOrigin, 0x0048, 31},
        LocoFunction{CentralOrigin, false, 0x0048, 4, 1, 7},
        LocoFunction{Booster, true, 0x0048, 4, 0x40, 5},
        LocoFunction{Booster, true, 0x0048, 4, 0x40, 6},
        AllDecoders{CentralOrigin, GroupAction::Off},
        AllDecoders{CentralOrigin, GroupAction::On},
        AllDecoders{CentralOrigin, GroupAction::Restore},
        DecoderSwitch{CentralOrigin, false, 0x3005, 0},
        DecoderSwitch{Decoder, true, 0x2E01, 7},
        AllEncoders{CentralOrigin, GroupAction::Off},
        AllEncoders{CentralOrigin, GroupAction::On},
        AllEncoders{CentralOrigin, GroupAction::Restore},
        EncoderQuery{CentralOrigin, false, 0x2E02},
        EncoderQuery{CentralOrigin, true, 0},
        EncoderStatus{Encoder, false, 0x2E02, 1, 0x05},
        EncoderStatus{Encoder, true, 0x2E02, 2, 0x8001},
        EncoderStatus{Encoder, true, 0x2E02, 3, 0x00FF00},
        EncoderStatus{Encoder, true, 0x2E02, 4, 0xDEADBEEF},
        Ping{Manager, 0x3A2E2E01},
        PingAnswer{Device, 0x3A2E2E01, 0x0102},
        Find{Manager, 0},
        FindAnswer{Device, 0x3A2E2E01, 0x0102},
        AssignBusId{Manager, false, 0x3A2E2E01, 0x2E03},
        AssignBusId{{prio::Management, 2, 0x2E03}, true, 0x3A2E2E01, 0x2E03},
        FlashCancel{Manager},
        FlashInit{Manager, Target::busId(0x2E01), 3},
        FlashInit{Manager, Target::uid(0x3A2E2E01), 3},
        FlashAccepted{Device, 0x2E01, 0x3A2E2E01, 2},
        FlashSize{Manager, 0x2E01, 0x001000, 0x0400, false},
        FlashSize{Manager, 0x2E01, 0x001000, 0x0400, true},
        FlashSizeAnswer{Device, 0x2E01, 0x8000, 255, false},
        FlashSizeAnswer{Device, 0x2E01, 0x8000, 255, true},
        FlashData{Manager, false, 0x2E01, 7, {1, 2, 3, 4}},
        FlashData{Device, true, 0x2E01, 7, {1, 2, 3, 4}},
        FlashChecksum{Manager, false, 0x2E01, 255, 0xCBF43926},
        FlashChecksum{Device, true, 0x2E01, 0, 0xCBF43926},
    };
}

} // namespace

TEST(Befehlssatz, EveryMessageRoundTrips) {
    for (const Message& message : samples()) {
        const can::CanFrame frame = encode(message);
        EXPECT_TRUE(isOrc(frame)) << nameOf(message);
        EXPECT_EQ(decode(frame), message) << nameOf(message) << " " << FrameReport(frame).text();
        EXPECT_EQ(encode(decode(frame)), frame) << nameOf(message);
    }
}

TEST(Befehlssatz, EveryMessageKindHasASample) {
    std::set<std::string_view> seen;
    for (const Message& message : samples())
        seen.insert(nameOf(message));
    for (const std::string_view name : messageNames()) {
        if (name != Unknown::name) {
            EXPECT_TRUE(seen.count(name)) << name;
        }
    }
}

TEST(Befehlssatz, UnknownFramesRoundTripAsSent) {
    const can::CanFrame frame =
        can::CanFrame::extendedFrame(0x11400000, std::array<std::uint8_t, 2>{0x07, 0x01});
    const Message message = decode(frame);
    ASSERT_TRUE(std::holds_alternative<Unknown>(message));
    EXPECT_EQ(encode(message), frame);
}

// Notes A3.2: only the bus-id messages Stellwerk adds are extensions; Find and Ping are the document's.
TEST(BusIdVergabe, ExtensionsAreMarked) {
    EXPECT_TRUE(isExtension(FindAnswer{}));
    EXPECT_TRUE(isExtension(AssignBusId{}));
    EXPECT_FALSE(isExtension(Find{}));
    EXPECT_FALSE(isExtension(PingAnswer{}));
}

// Every message can be built by name from key=value pairs (stellwerk-cli encode orc.<name>), and what is
// built is what decoding its frame gives back.
TEST(Befehlssatz, EveryMessageCanBeBuiltByName) {
    for (const std::string_view name : messageNames()) {
        if (name == Unknown::name)
            continue;
        const auto built = buildMessage(name, {{"prio", "2"}});
        ASSERT_TRUE(bool(built)) << name << ": " << built.error();
        EXPECT_EQ(nameOf(*built), name);
        EXPECT_EQ(decode(encode(*built)), *built) << name;
    }
}
