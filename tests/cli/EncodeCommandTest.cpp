#include "EncodeCommand.h"

#include "CommandRuns.h"

#include <gtest/gtest.h>
#include <sstream>

using stellwerk::cli::test::encode;

TEST(CliEncode, PrintsAllThreeNotations) {
    const auto run = encode({"loco.speed", "protocol=dcc", "address=3", "speed=288"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, "document: 00084711 6 00 00 C0 03 01 20\n"
                       "candump:  00084711#0000C0030120\n"
                       "network:  00084711060000C00301200000\n");
}

TEST(CliEncode, HashDefaultsToTheDocumentsExampleAndCanBeSet) {
    EXPECT_NE(encode({"system.stop"}).out.find("document: 00004711 5 00 00 00 00 00"), std::string::npos);
    EXPECT_NE(encode({"system.stop", "hash=0x0301"}).out.find("document: 00000301 5"), std::string::npos);
}

TEST(CliEncode, RefusesMessagesTheDecoderWouldRefuse) {
    const auto run = encode({"loco.speed", "locId=0xc003", "speed=1024"});
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err,
              "stellwerk-cli encode: loco.speed: reserved value: loco speed is a 10-bit value (0..1000, at "
              "most 1023)\n");
}

TEST(CliEncode, BadArgumentsSayWhatIsWrong) {
    EXPECT_EQ(encode({"loco.speed", "speed"}).err, "stellwerk-cli encode: 'speed' is not key=value\n");
    EXPECT_EQ(encode({"loco.speed", "speed"}).status, 2);
    const auto run = encode({"loco.fly", "x=1"});
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.err, "stellwerk-cli encode: unknown message name 'loco.fly'\n");
}

TEST(CliEncode, ListsTheVocabulary) {
    const auto run = encode({"--list"});
    EXPECT_EQ(run.status, 0);
    EXPECT_NE(run.out.find("  system.mfx-registration-counter\n"), std::string::npos);
    EXPECT_NE(run.out.find("  automation.switch\n"), std::string::npos);
    EXPECT_EQ(encode({}).status, 2);
}
