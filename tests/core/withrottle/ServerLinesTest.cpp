// Server lines from JMRI's WiThrottle protocol page ("Initial Connection", the multithrottle replies,
// "Property Change Notification", "Observations"), written byte for byte and read back.
#include "withrottle/ServerLines.h"

#include <gtest/gtest.h>

using namespace stellwerk::withrottle;

namespace {

void expectLine(const ServerLine& line, std::string_view text) {
    EXPECT_EQ(formatServerLine(line), text);
    const auto read = parseServerLine(text);
    ASSERT_TRUE(read.has_value()) << text;
    EXPECT_EQ(*read, line) << text;
}

} // namespace

TEST(WiThrottleServer, InitialConnectionVersionPowerWebPortHeartbeat) {
    expectLine(ProtocolVersion{}, "VN2.0");
    expectLine(PowerStatus{PowerState::Unknown}, "PPA2");
    expectLine(PowerStatus{PowerState::On}, "PPA1");
    expectLine(WebPort{12080}, "PW12080");
    expectLine(HeartbeatInterval{10}, "*10");
}

TEST(WiThrottleServer, RosterListExamples) {
    expectLine(RosterList{}, "RL0");
    expectLine(RosterList{{{"RGS 41", {41, true}}, {"Test Loco", {1234, true}}}},
               "RL2]\\[RGS 41}|{41}|{L]\\[Test Loco}|{1234}|{L");
    expectLine(RosterList{{{"D&RGW 341", {3, false}}, {"RGS 41", {41, true}}, {"Test Loco", {1234, true}}}},
               "RL3]\\[D&RGW 341}|{3}|{S]\\[RGS 41}|{41}|{L]\\[Test Loco}|{1234}|{L");
}

TEST(WiThrottleServer, TurnoutListTitlesAndStates) {
    expectLine(TurnoutTitles{}, "PTT]\\[Turnouts}|{Turnout]\\[Closed}|{2]\\[Thrown}|{4");
    expectLine(TurnoutList{{{"LT12", "Rico Station N", TurnoutState::Unknown},
                            {"LT324", "Rico Station S", TurnoutState::Closed}}},
               "PTL]\\[LT12}|{Rico Station N}|{1]\\[LT324}|{Rico Station S}|{2");
    expectLine(TurnoutChanged{"LT12", TurnoutState::Thrown}, "PTA4LT12");
}

TEST(WiThrottleServer, RouteListTitlesAndRoutes) {
    expectLine(RouteTitles{}, "PRT]\\[Routes}|{Route]\\[Active}|{2]\\[Inactive}|{4");
    expectLine(RouteList{{{"IR:AUTO:0001", "Rico Main", std::nullopt}}},
               "PRL]\\[IR:AUTO:0001}|{Rico Main}|{");
    expectLine(RouteList{{{"IR:AUTO:0002", "Yard", RouteState::Active}}}, "PRL]\\[IR:AUTO:0002}|{Yard}|{2");
    expectLine(RouteChanged{"IR:AUTO:0001", RouteState::Inactive}, "PRA4IR:AUTO:0001");
}

TEST(WiThrottleServer, AddLocomotiveReplyWithLabelsAndState) {
    expectLine(ThrottleReply{'T', ThrottleReplyKind::Added, "L41"}, "MT+L41<;>");
    expectLine(FunctionLabels{'T', "L41", {"Headlight", "Bell", "Whistle", "", ""}},
               "MTLL41<;>]\\[Headlight]\\[Bell]\\[Whistle]\\[]\\[");
    expectLine(LocoStatus{'T', "L41", FunctionState{0, false}}, "MTAL41<;>F00");
    expectLine(LocoStatus{'T', "L41", FunctionState{28, false}}, "MTAL41<;>F028");
    expectLine(LocoStatus{'T', "L41", SpeedState{0}}, "MTAL41<;>V0");
    expectLine(LocoStatus{'T', "L41", DirectionState{true}}, "MTAL41<;>R1");
    expectLine(LocoStatus{'T', "L41", SpeedStepState{1}}, "MTAL41<;>s1");
}

TEST(WiThrottleServer, PropertyChangeNotificationAndEmergencyStopSpeed) {
    expectLine(LocoStatus{'T', "L341", FunctionState{0, true}}, "MTAL341<;>F10");
    expectLine(LocoStatus{'0', "S3", SpeedState{-1}}, "M0AS3<;>V-1");
}

TEST(WiThrottleServer, ReleaseAndStealReplies) {
    expectLine(ThrottleReply{'T', ThrottleReplyKind::Removed, "L341"}, "MT-L341<;>");
    expectLine(ThrottleReply{'T', ThrottleReplyKind::StealNeeded, "L341"}, "MTSL341<;>L341");
}

TEST(WiThrottleServer, ObservationsServerTypeDescriptionMessage) {
    expectLine(ServerType{"Digitrax"}, "HTDigitrax");
    expectLine(ServerDescription{"Digitrax LnWi 1.0 Unit=7,Wifi Chnl= 1,Command Station= DCS100"},
               "HtDigitrax LnWi 1.0 Unit=7,Wifi Chnl= 1,Command Station= DCS100");
    expectLine(ServerMessage{"error - long address < 127 S23"}, "HMerror - long address < 127 S23");
}

TEST(WiThrottleServer, NamesCannotEndTheLineOrBreakTheList) {
    const std::string line =
        formatServerLine(RosterList{{{"Evil\nPPA0]\\[x}|{1}|{L", {3, false}}, {"Köf <;> II", {4, false}}}});
    EXPECT_EQ(line.find('\n'), std::string::npos);
    const auto read = parseServerLine(line);
    ASSERT_TRUE(read.has_value()) << line;
    const auto& roster = std::get<RosterList>(*read);
    ASSERT_EQ(roster.entries.size(), 2u);
    EXPECT_EQ(roster.entries[0].name, "Evil PPA0] [x} {1} {L");
    EXPECT_EQ(roster.entries[1].name, "Köf < > II");
}

TEST(WiThrottleServer, LinesItDoesNotReadAreNone) {
    for (const std::string_view line :
         {"RCC0", "RL2]\\[A}|{1}|{L", "PTL]\\[LT1}|{x}|{3", "MTAL41<;>F2", "PFT65871<;>4", "MT+L41<;>x",
          "PTT]\\[a}|{b]\\[c}|{3]\\[d}|{4", "RL1]\\[A}|{1}|{Q"})
        EXPECT_FALSE(parseServerLine(line).has_value()) << line;
}
