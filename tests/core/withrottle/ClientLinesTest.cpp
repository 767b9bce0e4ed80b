// Client lines from JMRI's WiThrottle protocol page, one test per section, read into messages.
#include "withrottle/ClientMessages.h"

#include <gtest/gtest.h>

using namespace stellwerk::withrottle;

namespace {

template <class T>
T read(std::string_view line) {
    const ClientMessage message = parseClientLine(line);
    EXPECT_TRUE(std::holds_alternative<T>(message)) << line << ": variant index " << message.index();
    return std::holds_alternative<T>(message) ? std::get<T>(message) : T{};
}

LocoAction action(std::string_view line) {
    return read<ThrottleAction>(line).action;
}

} // namespace

TEST(WiThrottleClient, DeviceNameAndHardwareInformation) {
    EXPECT_EQ(read<DeviceName>("NJohn's Throttle").name, "John's Throttle");
    EXPECT_EQ(read<HardwareId>("HU3f2a9b").id, "3f2a9b");
    EXPECT_EQ(read<ClientVersion>("VN2.0").version, "2.0");
}

TEST(WiThrottleClient, Heartbeat) {
    EXPECT_EQ(read<Heartbeat>("*").kind, HeartbeatKind::Beat);
    EXPECT_EQ(read<Heartbeat>("*+").kind, HeartbeatKind::MonitoringOn);
    EXPECT_EQ(read<Heartbeat>("*-").kind, HeartbeatKind::MonitoringOff);
}

TEST(WiThrottleClient, AddLocomotiveByAddressAndRosterEntry) {
    EXPECT_EQ(read<AcquireLoco>("MT+L341<;>ED&RGW 341"),
              (AcquireLoco{'T', "L341", RosterSelection{"D&RGW 341"}, false}));
    EXPECT_EQ(read<AcquireLoco>("MT+S3<;>ED&RGW 341").key, "S3");
    EXPECT_EQ(read<AcquireLoco>("M0+L3002<;>L3002"),
              (AcquireLoco{'0', "L3002", LocoAddress{3002, true}, false}));
    EXPECT_EQ(read<AcquireLoco>("M1+S79<;>S79").selection, LocoSelection(LocoAddress{79, false}));
}

TEST(WiThrottleClient, StealLocomotive) {
    EXPECT_EQ(read<AcquireLoco>("MTSL341<;>L341"), (AcquireLoco{'T', "L341", LocoAddress{341, true}, true}));
}

TEST(WiThrottleClient, RemoveLocomotiveReleaseAndDispatch) {
    EXPECT_EQ(read<ReleaseLoco>("MT-*<;>r"), (ReleaseLoco{'T', "*", false}));
    EXPECT_EQ(read<ReleaseLoco>("MT-L341<;>r"), (ReleaseLoco{'T', "L341", false}));
    EXPECT_EQ(read<ReleaseLoco>("MT-L341<;>d"), (ReleaseLoco{'T', "L341", true}));
}

TEST(WiThrottleClient, LocomotiveActionQueries) {
    EXPECT_EQ(read<ThrottleAction>("MTA*<;>qR"), (ThrottleAction{'T', "*", QueryDirection{}}));
    EXPECT_EQ(action("MTAL341<;>qV"), LocoAction(QuerySpeed{}));
}

TEST(WiThrottleClient, FunctionPressAndRelease) {
    EXPECT_EQ(action("MTA*<;>F112"), LocoAction(FunctionKey{12, true, false}));
    EXPECT_EQ(action("MTA*<;>F012"), LocoAction(FunctionKey{12, false, false}));
    EXPECT_EQ(action("MTAL341<;>F131"), LocoAction(FunctionKey{31, true, false}));
    EXPECT_EQ(action("MTAL341<;>f10"), LocoAction(FunctionKey{0, true, true}));
}

TEST(WiThrottleClient, SetDirectionAnyNonZeroIsForward) {
    EXPECT_EQ(action("MTA*<;>R0"), LocoAction(SetDirection{false}));
    EXPECT_EQ(action("MTA*<;>R1"), LocoAction(SetDirection{true}));
    EXPECT_EQ(action("MTA*<;>R5"), LocoAction(SetDirection{true}));
}

TEST(WiThrottleClient, SetSpeed0To126) {
    EXPECT_EQ(action("MTA*<;>V30"), LocoAction(SetSpeed{30}));
    EXPECT_EQ(action("MTA*<;>V0"), LocoAction(SetSpeed{0}));
    EXPECT_EQ(action("MTA*<;>V126"), LocoAction(SetSpeed{126}));
}

TEST(WiThrottleClient, EmergencyStopIdleAndSpeedStepMode) {
    EXPECT_EQ(action("MTA*<;>X"), LocoAction(EmergencyStop{}));
    EXPECT_EQ(action("MTA*<;>I"), LocoAction(Idle{}));
    EXPECT_EQ(action("MTAL41<;>s8"), LocoAction(SetSpeedStepMode{8}));
}

TEST(WiThrottleClient, PanelPowerTurnoutsRoutesAndQuit) {
    EXPECT_EQ(read<SetPower>("PPA1").on, true);
    EXPECT_EQ(read<SetPower>("PPA0").on, false);
    EXPECT_EQ(read<SwitchTurnout>("PTA2LT12"), (SwitchTurnout{TurnoutAction::Toggle, "LT12"}));
    EXPECT_EQ(read<SwitchTurnout>("PTATLT324"), (SwitchTurnout{TurnoutAction::Throw, "LT324"}));
    EXPECT_EQ(read<SwitchTurnout>("PTACLT324"), (SwitchTurnout{TurnoutAction::Close, "LT324"}));
    EXPECT_EQ(read<SetRoute>("PRA2IR:AUTO:0001").systemName, "IR:AUTO:0001");
    read<Quit>("Q");
}

TEST(WiThrottleClient, UnknownCommandsAreIgnoredAsUnknownLines) {
    for (const std::string_view line :
         {"D0123", "RC+<;>S74<;>My consist<:>L341<;>true", "MTA*<;>V127", "MTA*<;>V-1", "MTA*<;>F132",
          "MTA*<;>F2", "MTA*<;>Vx", "MT+<;>L341", "MT+L341", "MTZL341<;>r", "MT-L341<;>x", "PPA2", "PTAX12",
          "PRA1Route", "N", "M", "", "MTAL341<;>CL346", "MT+L341<;>L99999"})
        EXPECT_EQ(parseClientLine(line), ClientMessage(UnknownLine{std::string(line)})) << line;
}
