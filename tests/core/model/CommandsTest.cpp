// The commands the railway sends (model/Commands.h), encoded and compared with the frames of Märklin's
// CS2 CAN protocol document (shared/seeds/003_e81750172fa08e9b.txt) as tests/core/cs2/DocumentChapter*Test
// quote them. The document's frames carry hash 0x4711; the test stamps it as the station session stamps
// its own, and checks that the builders leave the header to the session.

#include "model/Commands.h"

#include "can/FrameText.h"
#include "cs2/Codec.h"

#include <gtest/gtest.h>
#include <string>
#include <string_view>

namespace stellwerk::model::commands {
namespace {

constexpr std::uint16_t DocumentHash = 0x4711;

// The command's frame in document notation, with the document's hash stamped on it.
std::string onWire(cs2::Message command) {
    EXPECT_EQ(command.prio, 0);
    EXPECT_FALSE(command.response);
    EXPECT_EQ(command.hash, 0) << "the session stamps the hash, not the model";
    command.hash = DocumentHash;
    return can::formatDocument(cs2::encode(command));
}

// A frame as the document prints it, without its comment.
std::string document(std::string_view text) {
    const auto parsed = can::parseFrame(text);
    EXPECT_TRUE(parsed.hasValue()) << text;
    return parsed ? can::formatDocument(parsed->frame) : std::string();
}

TEST(RailwayCommands, SpeedOfMfxLoco1Is800) {
    // 3.4: "00084711 6 00 00 40 01 03 20 Lok Geschwindigkeit mfx Adr 1, V=0x0320=800".
    EXPECT_EQ(onWire(speed(cs2::LocId(0x4001), 800)), document("00084711 6 00 00 40 01 03 20"));
}

TEST(RailwayCommands, DirectionForwardAndBackward) {
    // 3.5, set form (DLC 5): 1 forward, 2 backward.
    EXPECT_EQ(onWire(direction(cs2::LocId(0xC003), cs2::Direction::Forward)),
              document("000A4711 5 00 00 C0 03 01"));
    EXPECT_EQ(onWire(direction(cs2::LocId(0x4005), cs2::Direction::Backward)),
              document("000A4711 5 00 00 40 05 02"));
}

TEST(RailwayCommands, FunctionOnAndOff) {
    // 3.6, set form (DLC 6): MM2 loco 72, F1 on, then off.
    EXPECT_EQ(onWire(function(cs2::LocId(0x0048), 1, true)), document("000C4711 6 00 00 00 48 01 01"));
    EXPECT_EQ(onWire(function(cs2::LocId(0x0048), 1, false)), document("000C4711 6 00 00 00 48 01 00"));
}

TEST(RailwayCommands, EmergencyStopOfMm2Loco72) {
    // 2.4: "00004711 5 00 00 00 48 03 Lok Nothalt MM2 72".
    EXPECT_EQ(onWire(emergencyStop(cs2::LocId(0x0048))), document("00004711 5 00 00 00 48 03"));
}

TEST(RailwayCommands, StopAndGoToAll) {
    // 2.1 "Stopp an alle" and 2.2 "Go an alle".
    EXPECT_EQ(onWire(stop()), document("00004711 5 00 00 00 00 00"));
    EXPECT_EQ(onWire(go()), document("00004711 5 00 00 00 00 01"));
}

TEST(RailwayCommands, SwitchOutputWithDefaultTime) {
    // 4.1, DLC 6: MM2 article 0x3003, output 1, current on; the station's default switch time.
    EXPECT_EQ(onWire(switchOutput(cs2::LocId(0x3003), 1)), document("00164711 6 00 00 30 03 01 01"));
}

TEST(RailwayCommands, SwitchOutputWithSwitchTime) {
    // 4.1, DLC 8: DCC article 0x3800, output 0, switch time 10 x 10 ms.
    EXPECT_EQ(onWire(switchOutput(cs2::LocId(0x3800), 0, 10)),
              document("00164711 8 00 00 38 00 00 01 00 0A"));
}

TEST(RailwayCommands, ReadAndWriteStatusChannel) {
    // 2.12: read channel 1 (DLC 6); set channel 5 to 500 (DLC 8).
    EXPECT_EQ(onWire(readChannel(0x43533208, 1)), document("00004711 6 43 53 32 08 0B 01"));
    EXPECT_EQ(onWire(writeChannel(0x43533208, 5, 500)), document("00004711 8 43 53 32 08 0B 05 01 F4"));
}

TEST(RailwayCommands, ReadOneCvByte) {
    // 3.7: DCC address 3, CV 1, one byte.
    EXPECT_EQ(onWire(readCv(cs2::LocId(0xC003), {1, 0})), document("000E4711 7 00 00 C0 03 00 01 01"));
}

TEST(RailwayCommands, ReadCvCarriesTheMfxIndex) {
    // 3.7/3.8: the 6-bit index sits above the 10-bit CV number.
    EXPECT_EQ(onWire(readCv(cs2::LocId(0x4005), {3, 2})), document("000E4711 7 00 00 40 05 08 03 01"));
}

TEST(RailwayCommands, WriteCvOnTheProgrammingTrackInEachDccMode) {
    // 3.8: control byte 0x00 direct, 0x10 register, 0x20 bit; DCC address 3, CV 1 = 3.
    const cs2::LocId decoder(0xC003);
    EXPECT_EQ(onWire(writeCv(decoder, {1, 0}, 3, false, cs2::DccProgrammingMode::Direct)),
              document("00104711 8 00 00 C0 03 00 01 03 00"));
    EXPECT_EQ(onWire(writeCv(decoder, {1, 0}, 3, false, cs2::DccProgrammingMode::Register)),
              document("00104711 8 00 00 C0 03 00 01 03 10"));
    EXPECT_EQ(onWire(writeCv(decoder, {1, 0}, 3, false, cs2::DccProgrammingMode::Bit)),
              document("00104711 8 00 00 C0 03 00 01 03 20"));
}

TEST(RailwayCommands, WriteCvOnTheMainTrack) {
    // 3.8: bit 8 (0x80) main track; bit mode 0x20; never a multi-byte write (0x40).
    EXPECT_EQ(onWire(writeCv(cs2::LocId(0xC003), {29, 0}, 0xFD, true, cs2::DccProgrammingMode::Bit)),
              document("00104711 8 00 00 C0 03 00 1D FD A0"));
}

TEST(RailwayCommands, FullMfxDiscoveryCycle) {
    // 3.1: "00024711 1 20 Voller mfx Discoveryzyklus".
    EXPECT_EQ(onWire(discoverMfx(32)), document("00024711 1 20"));
}

TEST(RailwayCommands, BindAndVerifyMfxDecoder) {
    // 3.2 "Bind UID: FF FA 8C 43 auf SID: 05" and 3.3 "Verify FF FA 8C 43 auf SID 05".
    EXPECT_EQ(onWire(bindMfx(0xFFFA8C43, 5)), document("00044711 6 FF FA 8C 43 00 05"));
    EXPECT_EQ(onWire(verifyMfx(0xFFFA8C43, 5)), document("00064711 6 FF FA 8C 43 00 05"));
}

} // namespace
} // namespace stellwerk::model::commands
