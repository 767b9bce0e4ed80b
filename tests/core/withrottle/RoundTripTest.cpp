// Every client message and every server line, formatted and read back to the same value.
#include "withrottle/ServerLines.h"

#include <gtest/gtest.h>

using namespace stellwerk::withrottle;

TEST(WiThrottleRoundTrip, EveryClientMessage) {
    const std::vector<ClientMessage> messages = {DeviceName{"Engine Driver"},
                                                 HardwareId{"a1b2"},
                                                 ClientVersion{"2.0"},
                                                 Heartbeat{HeartbeatKind::MonitoringOff},
                                                 SetPower{true},
                                                 SwitchTurnout{TurnoutAction::Close, "12"},
                                                 SetRoute{"Einfahrt West"},
                                                 Quit{},
                                                 AcquireLoco{'3', "S3", LocoAddress{3, false}, false},
                                                 AcquireLoco{'T', "E1", RosterSelection{"BR 86"}, true},
                                                 ReleaseLoco{'T', "*", true},
                                                 ThrottleAction{'1', "L1000", SetSpeed{126}},
                                                 ThrottleAction{'1', "*", SetDirection{false}},
                                                 ThrottleAction{'1', "*", FunctionKey{31, false, true}},
                                                 ThrottleAction{'1', "*", QuerySpeed{}},
                                                 ThrottleAction{'1', "*", QueryDirection{}},
                                                 ThrottleAction{'1', "*", EmergencyStop{}},
                                                 ThrottleAction{'1', "*", Idle{}},
                                                 ThrottleAction{'1', "*", SetSpeedStepMode{16}},
                                                 UnknownLine{"RCC0"}};
    for (const ClientMessage& message : messages)
        EXPECT_EQ(parseClientLine(formatClientLine(message)), message) << formatClientLine(message);
}

TEST(WiThrottleRoundTrip, EveryServerLine) {
    const std::vector<ServerLine> lines = {ProtocolVersion{},
                                           RosterList{{{"BR 86", {86, false}}, {"Köf", {10001, true}}}},
                                           PowerStatus{PowerState::Off},
                                           TurnoutTitles{"Weichen", "Weiche", "Gerade", "Abzweig"},
                                           TurnoutList{},
                                           TurnoutChanged{"1", TurnoutState::Closed},
                                           RouteTitles{},
                                           RouteList{{{"1", "Einfahrt", RouteState::Unknown}}},
                                           RouteChanged{"2", RouteState::Active},
                                           WebPort{80},
                                           HeartbeatInterval{0},
                                           ServerType{"Stellwerk"},
                                           ServerDescription{"Stellwerk 1.0"},
                                           ServerMessage{"Locomotive taken by the desk"},
                                           ThrottleReply{'6', ThrottleReplyKind::Added, "L3002"},
                                           FunctionLabels{'6', "L3002", {}},
                                           LocoStatus{'6', "L3002", SpeedStepState{2}}};
    for (const ServerLine& line : lines) {
        const auto read = parseServerLine(formatServerLine(line));
        ASSERT_TRUE(read.has_value()) << formatServerLine(line);
        EXPECT_EQ(*read, line) << formatServerLine(line);
    }
}
