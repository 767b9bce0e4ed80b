#include "cs2/FrameReport.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2;

TEST(FrameReport, TextLineShowsFrameNameAndFields) {
    const FrameReport report(test::frame("00084711 6 00 00 C0 03 01 20"));
    EXPECT_TRUE(report.ok());
    EXPECT_EQ(report.text(),
              "00084711 6 00 00 C0 03 01 20  loco.speed locId=0xC003 protocol=dcc address=3 speed=288");
}

TEST(FrameReport, TextLineMarksResponsesAndQuotesTextWithSpaces) {
    const FrameReport report(test::frame("00314711 8 47 43 F5 DA 01 3E 00 10"));
    EXPECT_EQ(report.text(),
              "00314711 8 47 43 F5 DA 01 3E 00 10  ping (response) uid=0x4743F5DA version=1.62 "
              "deviceType=0x0010 deviceName=\"Gleisbox 60112/60113\"");
}

TEST(FrameReport, JsonCarriesTheAgreedKeys) {
    const FrameReport report(test::frame("00014711 8 43 53 32 08 0B 01 00 03"));
    EXPECT_EQ(report.json(),
              "{\"id\":\"00014711\",\"prio\":0,\"command\":0,\"response\":true,\"hash\":\"4711\",\"dlc\":8,"
              "\"data\":\"435332080B010003\",\"name\":\"system.status\",\"fields\":{\"uid\":\"0x43533208\","
              "\"subcommand\":\"0x0B\",\"channel\":1,\"value\":3}}");
}

TEST(FrameReport, ErrorsKeepTheIntendedNameAndExplain) {
    const FrameReport report(test::frame("00084711 5 00 00 C0 03 01"));
    EXPECT_FALSE(report.ok());
    EXPECT_EQ(report.name(), "loco.speed");
    EXPECT_EQ(report.text(),
              "00084711 5 00 00 C0 03 01  loco.speed  ERROR unexpected length 5: loco.speed has 4 "
              "(query) or 6 data bytes");
    EXPECT_NE(report.json().find("\"fields\":{\"error\":\"unexpected length 5: "), std::string::npos);
    EXPECT_NE(report.json().find("\"errorKind\":\"unexpected-length\""), std::string::npos);
}

TEST(FrameReport, JsonEscapesFileNameBytes) {
    const FrameReport report(test::frame("00404711 8 22 5C 01 00 00 00 00 00"));
    EXPECT_NE(report.json().find("\"filename\":\"\\\"\\\\x5C\\\\x01\""), std::string::npos) << report.json();
}

TEST(FrameReport, IntendedNamesCoverSystemSubcommands) {
    EXPECT_EQ(intendedName(test::frame("00004711 7 00 00 00 00 0B 01 05")), "system.status");
    EXPECT_EQ(intendedName(test::frame("00004711 4 00 00 00 00")), "unknown");
    EXPECT_EQ(intendedName(test::frame("00424711 3 00 00 00")), "configdata.stream");
}
