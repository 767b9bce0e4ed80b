#include "DecodeCommand.h"

#include "../core/mcan/SeedTrace.h"
#include "CommandRuns.h"
#include "can/FrameText.h"

#include <gtest/gtest.h>
#include <sstream>

using stellwerk::cli::test::decode;

TEST(CliDecode, ArgumentsInEveryNotationGiveOneLineEach) {
    const auto run = decode({"00004711 5 00 00 00 00 00", "00004711#0000000000", "00004711050000000000000000",
                             "(1.0) can0 00004711#0000000000"});
    EXPECT_EQ(run.status, 0);
    const std::string line = "00004711 5 00 00 00 00 00  system.stop uid=0x00000000 subcommand=0x00\n";
    EXPECT_EQ(run.out, line + line + line + line);
    EXPECT_EQ(run.err, "");
}

TEST(CliDecode, ReadsStdinSkippingBlankAndCommentLines) {
    const auto run = decode({}, "# a captured session\n\n00084711 6 00 00 C0 03 01 20\n   \n00304711#\n");
    EXPECT_EQ(run.status, 0);
    EXPECT_EQ(run.out,
              "00084711 6 00 00 C0 03 01 20  loco.speed locId=0xC003 protocol=dcc address=3 speed=288\n"
              "00304711 0  ping\n");
}

TEST(CliDecode, JsonLinesCarryTheAgreedKeys) {
    const auto run = decode({"--json", "00084711 6 00 00 C0 03 01 20"});
    EXPECT_EQ(run.status, 0);
    EXPECT_EQ(run.out, "{\"protocol\":\"cs2\",\"id\":\"00084711\",\"prio\":0,\"command\":4,\"response\":"
                       "false,\"hash\":\"4711\",\"dlc\":6,"
                       "\"data\":\"0000C0030120\",\"name\":\"loco.speed\",\"fields\":{\"locId\":\"0xC003\","
                       "\"protocol\":\"dcc\",\"address\":3,\"speed\":288}}\n");
}

// Standard (11-bit) frames belong to no protocol of a station's bus (CS2, M-CAN): shown as foreign, with
// their id in 3 digits.
TEST(CliDecode, StandardFramesAreShownAsForeign) {
    const auto text = decode({"123#0102"});
    EXPECT_EQ(text.status, 0);
    EXPECT_EQ(text.out, "123 2 01 02  foreign 11-bit frame (no protocol of a CS2/M-CAN bus)\n");
    const auto json = decode({"--json", "can0  7FF   [1]  AB"});
    EXPECT_EQ(json.out,
              "{\"protocol\":\"foreign\",\"id\":\"7FF\",\"extended\":false,\"dlc\":1,\"data\":\"AB\"}\n");
}

// candump -x prints the direction and flags between the interface and the identifier.
TEST(CliDecode, ReadsCandumpExtraDetailLines) {
    const auto run = decode({}, "  can0  RX - -  00004711   [5]  00 00 00 00 00\n");
    EXPECT_EQ(run.status, 0);
    EXPECT_EQ(run.out, "00004711 5 00 00 00 00 00  system.stop uid=0x00000000 subcommand=0x00\n");
}

TEST(CliDecode, BadFramesAreReportedAndTheRestStillDecode) {
    const auto run = decode(
        {}, "00004711 5 00 00 00 00 00\nnot a frame\n00084711 5 00 00 C0 03 01\n00004711 5 00 00 00 00 01\n");
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.out,
              "00004711 5 00 00 00 00 00  system.stop uid=0x00000000 subcommand=0x00\n"
              "00084711 5 00 00 C0 03 01  loco.speed  ERROR unexpected length 5: loco.speed has 4 (query) "
              "or 6 data bytes\n"
              "00004711 5 00 00 00 00 01  system.go uid=0x00000000 subcommand=0x01\n");
    EXPECT_EQ(run.err,
              "stellwerk-cli decode: line 2: 'not' is not a hexadecimal CAN identifier: not a frame\n");
}

TEST(CliDecode, JsonModeReportsUnreadableLinesAsJson) {
    const auto run = decode({"--json", "00004711 7 00 00 00 00 06 0A"});
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.out,
              "{\"input\":\"00004711 7 00 00 00 00 06 0A\",\"error\":\"DLC 7 announces 7 data bytes, only 6 "
              "given\"}\n");
}

TEST(CliDecode, DlcAboveEightIsAnErrorLine) {
    const auto run = decode({"00004711 9 00 00 00 00 00 00 00 00"});
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.out.find("ERROR DLC 9 is above 8"), std::string::npos) << run.out;
}

// Issue 32: with fewer bytes than eight the line named the missing bytes instead of the DLC.
TEST(CliDecode, DlcAboveEightWithOneByteSaysTheDlcIsAboveEight) {
    const auto run = decode({"00164711 9 00"});
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err, "stellwerk-cli decode: line 1: DLC 9 is above 8: a CAN frame has at most 8 data bytes "
                       "(1 given): 00164711 9 00\n");
    const auto json = decode({"--json", "00164711 9 00"});
    EXPECT_EQ(json.out,
              "{\"input\":\"00164711 9 00\",\"error\":\"DLC 9 is above 8: a CAN frame has at most 8 "
              "data bytes (1 given)\"}\n");
}

TEST(CliDecode, UnknownOptionIsAUsageError) {
    const auto run = decode({"--yaml"});
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(run.err, "stellwerk-cli decode: unknown option --yaml\n");
}

// Issue 11 (found by fuzzing): a byte above 0x7F in an unreadable line was copied into the JSON as it
// was, which is not UTF-8. Bytes that are not UTF-8 are written as their Latin-1 character.
TEST(CliDecode, JsonEscapesBytesThatAreNotUtf8) {
    const auto run = decode({"--json"}, "\xe4\n");
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.out.rfind("{\"input\":\"\\u00e4\",\"error\":\"'\\u00e4' is not", 0), 0u) << run.out;
}

TEST(CliDecode, JsonKeepsUtf8AndEscapesControlCharacters) {
    const auto run = decode({"--json"}, "Gr\xc3\xbc\xc3\x9f\x1b[2J\n");
    EXPECT_EQ(run.out.rfind("{\"input\":\"Gr\xc3\xbc\xc3\x9f\\u001b[2J\",", 0), 0u) << run.out;
}

namespace {

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

// The chapter-11 trace of the M-CAN document (an MS1 logging into an ECoS), one frame per line.
std::string chapter11Input() {
    std::string input;
    for (const stellwerk::can::CanFrame& frame :
         stellwerk::seeds::chapter11Trace(stellwerk::seeds::McanSeed002))
        input += stellwerk::can::formatDocument(frame) + '\n';
    return input;
}

} // namespace

// M-CAN notes B§4.2, trace #82: an MS1 (node 43) polls its master. A poll says itself which handle is the
// poll handle, so even a lone poll names it.
TEST(CliDecode, McanFramesDecodeWithProtocolMcan) {
    const auto text = decode({"0C0007AB 4 00 00 00 2A"});
    EXPECT_EQ(text.status, 0);
    EXPECT_EQ(text.out,
              "0C0007AB 4 00 00 00 2A  mcan.poll  from=slave node=43 handle=0x0001 prio=3 masterNode=42 "
              "object=poll\n");
    const auto json = decode({"--json", "0C0007AB#0000002A"});
    EXPECT_EQ(json.status, 0);
    EXPECT_EQ(json.out, "{\"protocol\":\"mcan\",\"id\":\"0C0007AB\",\"dlc\":4,\"data\":\"0000002A\",\"name\":"
                        "\"mcan.poll\",\"fields\":{\"from\":\"slave\",\"node\":43,\"handle\":\"0x0001\","
                        "\"prio\":3,\"masterNode\":42,\"object\":\"poll\"}}\n");
}

// The lines of one run are one bus: the SY handle given in #30 makes #31 a status query (alone it reads as
// a function query), and the loco handle and name given in #46 and #77-81 name the loco taken in #92.
TEST(CliDecode, TheChapter11TraceReadsAsOneBus) {
    const std::string input = chapter11Input();
    ASSERT_FALSE(input.empty()) << "the seed document is read in place from ../shared/seeds";
    const auto run = decode({}, input);
    const std::vector<std::string> lines = linesOf(run.out);
    ASSERT_EQ(lines.size(), 99u);
    EXPECT_EQ(lines[30],
              "18000D2B 2 01 01  mcan.status-query  from=slave node=43 handle=0x0003 prio=6 index=1 "
              "asks=type object=system-status");
    EXPECT_NE(lines[91].find("mcan.throttle  from=slave node=43 handle=0x0009 prio=5"), std::string::npos)
        << lines[91];
    EXPECT_NE(lines[91].find("object=loco loco=\"003 131-0\""), std::string::npos) << lines[91];
    EXPECT_NE(decode({"18000D2B 2 01 01"}).out.find("mcan.function-query"), std::string::npos);
    const auto json = linesOf(decode({"--json"}, input).out);
    ASSERT_EQ(json.size(), 99u);
    EXPECT_NE(json[91].find("\"object\":\"loco\",\"loco\":\"003 131-0\""), std::string::npos) << json[91];
    EXPECT_EQ(json[91].rfind("{\"protocol\":\"mcan\",", 0), 0u) << json[91];
}
