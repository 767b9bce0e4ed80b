// stellwerk-cli decode and encode with OpenRailCAN frames (ORC notes A4.2 vectors, Derived; notes C7).

#include "CommandRuns.h"
#include "DecodeCommand.h"
#include "EncodeCommand.h"

#include <gtest/gtest.h>
#include <sstream>

using stellwerk::cli::test::decode;
using stellwerk::cli::test::encode;

// Notes A4.2 V5 (Derived): on a station's bus (auto), a frame M-CAN cannot read but ORC can is ORC.
TEST(CliOrcDecode, DerivedDecoderSwitchReadsAsOrcByDefault) {
    const auto run = decode({"11100000 4 03 30 05 01"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, "11100000 4 03 30 05 01  orc.decoder.switch  prio=2 type=system sender=0x0000 "
                       "direction=command target=0x3005 legacy=mm2-decoder number=5 position=1\n");
}

// Notes A4.2 V8 (Derived) as JSON on a bus declared as ORC beside a CS2.
TEST(CliOrcDecode, DerivedEncoderEventAsJsonOnAnOrcBus) {
    const auto run = decode({"--json", "--protocol", "orc", "17122E01 4 10 2E 01 05"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out,
              "{\"protocol\":\"orc\",\"id\":\"17122E01\",\"dlc\":4,\"data\":\"102E0105\","
              "\"name\":\"orc.encoder.status\",\"fields\":{\"prio\":2,\"type\":\"can-encoder\","
              "\"sender\":\"0x2E01\",\"direction\":\"command\",\"encoder\":\"0x2E01\",\"inputCount\":8,"
              "\"inputs\":\"0x05\",\"event\":\"event\"}}\n");
}

// A malformed ORC frame on an ORC bus: shown with the reason, exit code 1.
TEST(CliOrcDecode, MalformedFrameGivesItsReasonAndExitCode1) {
    const auto run = decode({"--protocol=orc", "11100000 3 03 30 05"});
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.out.find("orc.unknown"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("why=\"dekoder schalten takes DLC 4 (Ziel-Id, Pos)\""), std::string::npos)
        << run.out;
}

// With --protocol mcan the station's bus is read as before: the overlap goes to M-CAN (notes O26).
TEST(CliOrcDecode, McanOnlyBusLeavesTheOverlapToMcan) {
    const auto run = decode({"--protocol", "mcan", "11100000 4 03 30 05 01"});
    EXPECT_EQ(run.out.find("orc."), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("mcan."), std::string::npos) << run.out;
}

TEST(CliOrcDecode, UnknownProtocolIsAUsageError) {
    const auto run = decode({"--protocol", "zcan", "11100000 4 03 30 05 01"});
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(run.err, "stellwerk-cli decode: --protocol zcan: use auto, cs2, mcan or orc\n");
}

// 001 §Genereller Aufbau der Befehle: MM2 Weiche 5 = Ziel-Id 0x3005; the frame is notes A4.2 V5 (Derived).
TEST(CliOrcEncode, DecoderSwitchOfMm2Weiche5) {
    const auto run = encode({"orc.decoder.switch", "target=0x3005", "position=1"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, "document: 11100000 4 03 30 05 01\n"
                       "candump:  11100000#03300501\n"
                       "network:  11100000040330050100000000\n");
}

// Notes A4.2 V10 (Derived): the envelope keys type, sender and prio.
TEST(CliOrcEncode, PingAnswerWithSenderTypeAndPriority) {
    const auto run = encode({"orc.mgmt.pingAnswer", "uid=0x3A2E2E01", "version=0x0102", "type=can-decoder",
                             "sender=0x2E01", "prio=3"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("document: 1D212E01 7 00 3A 2E 2E 01 01 02\n"), std::string::npos) << run.out;
}

TEST(CliOrcEncode, BusIdAssignmentExtension) {
    const auto run = encode({"orc.mgmt.assign", "uid=0x3A2E2E01", "busId=0x2E02"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("document: 19200000 7 02 3A 2E 2E 01 2E 02\n"), std::string::npos) << run.out;
}

TEST(CliOrcEncode, BadValuesAreRefusedWithTheKey) {
    EXPECT_EQ(encode({"orc.decoder.switch", "target=0x3005", "position=300"}).err,
              "stellwerk-cli encode: orc.decoder.switch: position=300 is out of range 0..255\n");
    EXPECT_EQ(encode({"orc.decoder.switch", "prio=0"}).err,
              "stellwerk-cli encode: orc.decoder.switch: prio=0 is out of range 1..3\n");
    EXPECT_EQ(encode({"orc.decoder.switch", "tgt=5"}).status, 1);
    EXPECT_EQ(encode({"orc.decoder.switch", "tgt=5"}).err,
              "stellwerk-cli encode: orc.decoder.switch: unknown key 'tgt' (keys: prio type sender target "
              "position answer)\n");
    EXPECT_EQ(encode({"orc.nothing"}).err,
              "stellwerk-cli encode: unknown OpenRailCAN message 'orc.nothing' (see encode --list)\n");
    EXPECT_EQ(encode({"orc.decoder.switch", "target"}).status, 2);
}

TEST(CliOrcEncode, ListNamesOrcMessages) {
    const auto run = encode({"--list"});
    EXPECT_EQ(run.status, 0);
    EXPECT_NE(run.out.find("  orc.encoder.status  encoder inputs count=8|16|24|32 answer\n"),
              std::string::npos);
}
