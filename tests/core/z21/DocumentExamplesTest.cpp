// The byte sequences printed in Roco's Z21 LAN protocol specification (English v1.10; the German v1.13
// for 4.5), one test per section; each request is read, each reply written byte for byte.
#include "Z21TestSupport.h"

using namespace stellwerk::z21;
using namespace stellwerk::z21::test;

TEST(Z21Spec, Section2_1_GetSerialNumber) {
    onlyRequestOf<GetSerialNumber>({0x04, 0x00, 0x10, 0x00});
    EXPECT_EQ(encodeReply(SerialNumber{0x12345678}), (Bytes{0x08, 0x00, 0x10, 0x00, 0x78, 0x56, 0x34, 0x12}));
}

TEST(Z21Spec, Section2_2_Logoff) {
    onlyRequestOf<Logoff>({0x04, 0x00, 0x30, 0x00});
}

TEST(Z21Spec, Section2_3_GetVersionAndItsReply) {
    onlyRequestOf<GetXVersion>({0x07, 0x00, 0x40, 0x00, 0x21, 0x21, 0x00});
    EXPECT_EQ(encodeReply(XVersion{}), (Bytes{0x09, 0x00, 0x40, 0x00, 0x63, 0x21, 0x30, 0x12, 0x60}));
}

TEST(Z21Spec, Section2_4_GetStatus) {
    onlyRequestOf<GetXStatus>({0x07, 0x00, 0x40, 0x00, 0x21, 0x24, 0x05});
}

TEST(Z21Spec, Section2_5And2_6_TrackPowerOffAndOn) {
    onlyRequestOf<SetTrackPowerOff>({0x07, 0x00, 0x40, 0x00, 0x21, 0x80, 0xA1});
    onlyRequestOf<SetTrackPowerOn>({0x07, 0x00, 0x40, 0x00, 0x21, 0x81, 0xA0});
}

TEST(Z21Spec, Sections2_7To2_11_Broadcasts) {
    EXPECT_EQ(encodeReply(TrackPowerOff{}), (Bytes{0x07, 0x00, 0x40, 0x00, 0x61, 0x00, 0x61}));
    EXPECT_EQ(encodeReply(TrackPowerOn{}), (Bytes{0x07, 0x00, 0x40, 0x00, 0x61, 0x01, 0x60}));
    EXPECT_EQ(encodeReply(ProgrammingMode{}), (Bytes{0x07, 0x00, 0x40, 0x00, 0x61, 0x02, 0x63}));
    EXPECT_EQ(encodeReply(TrackShortCircuit{}), (Bytes{0x07, 0x00, 0x40, 0x00, 0x61, 0x08, 0x69}));
    EXPECT_EQ(encodeReply(UnknownCommand{}), (Bytes{0x07, 0x00, 0x40, 0x00, 0x61, 0x82, 0xE3}));
}

TEST(Z21Spec, Section2_12_StatusChanged) {
    const Bytes bytes = encodeReply(XStatusChanged{central::EmergencyStop | central::TrackVoltageOff});
    EXPECT_EQ(bytes, (Bytes{0x08, 0x00, 0x40, 0x00, 0x62, 0x22, 0x03, 0x62 ^ 0x22 ^ 0x03}));
}

TEST(Z21Spec, Section2_13And2_14_StopAndStopped) {
    onlyRequestOf<SetStop>({0x06, 0x00, 0x40, 0x00, 0x80, 0x80});
    EXPECT_EQ(encodeReply(Stopped{}), (Bytes{0x07, 0x00, 0x40, 0x00, 0x81, 0x00, 0x81}));
}

TEST(Z21Spec, Section2_15_FirmwareVersion123) {
    onlyRequestOf<GetFirmwareVersion>({0x07, 0x00, 0x40, 0x00, 0xF1, 0x0A, 0xFB});
    const Bytes example{0x09, 0x00, 0x40, 0x00, 0xF3, 0x0A, 0x01, 0x23, 0xDB};
    EXPECT_EQ(encodeReply(FirmwareVersion{bcdVersion(1, 23)}), example);
    EXPECT_EQ(onlyReplyOf<FirmwareVersion>(example).version, 0x0123);
}

TEST(Z21Spec, Section2_16And2_17_BroadcastFlagsLittleEndian) {
    const auto set = onlyRequestOf<SetBroadcastFlags>({0x08, 0x00, 0x50, 0x00, 0x01, 0x01, 0x01, 0x00});
    EXPECT_EQ(set.flags, broadcast::DrivingAndSwitching | broadcast::SystemState | broadcast::AllLocos);
    onlyRequestOf<GetBroadcastFlags>({0x04, 0x00, 0x51, 0x00});
    EXPECT_EQ(encodeReply(BroadcastFlags{0x00000101}),
              (Bytes{0x08, 0x00, 0x51, 0x00, 0x01, 0x01, 0x00, 0x00}));
}

TEST(Z21Spec, Section2_18_SystemStateLayout) {
    const SystemState state{-5,  20, 300, 35, 18000, 16000, central::TrackVoltageOff, central::PowerLost,
                            0x13};
    const Bytes bytes = encodeReply(state);
    ASSERT_EQ(bytes.size(), 0x14u);
    EXPECT_EQ(Bytes(bytes.begin(), bytes.begin() + 4), (Bytes{0x14, 0x00, 0x84, 0x00}));
    EXPECT_EQ(Bytes(bytes.begin() + 4, bytes.begin() + 8), (Bytes{0xFB, 0xFF, 0x14, 0x00}));   // -5 mA, 20 mA
    EXPECT_EQ(Bytes(bytes.begin() + 12, bytes.begin() + 16), (Bytes{0x50, 0x46, 0x80, 0x3E})); // 18 V, 16 V
    EXPECT_EQ(Bytes(bytes.begin() + 16, bytes.end()), (Bytes{0x02, 0x02, 0x00, 0x13}));
    onlyRequestOf<GetSystemState>({0x04, 0x00, 0x85, 0x00});
}

TEST(Z21Spec, Section2_20_HardwareInfoExample) {
    onlyRequestOf<GetHardwareInfo>({0x04, 0x00, 0x1A, 0x00});
    const Bytes example{0x0C, 0x00, 0x1A, 0x00, 0x00, 0x02, 0x00, 0x00, 0x20, 0x01, 0x00, 0x00};
    EXPECT_EQ(encodeReply(HardwareInfo{0x200, bcdVersion(1, 20)}), example);
}

TEST(Z21Spec, Section2_21_GetCodeAnsweredNotLocked) {
    onlyRequestOf<GetCode>({0x04, 0x00, 0x18, 0x00});
    EXPECT_EQ(encodeReply(FeatureCode{}), (Bytes{0x05, 0x00, 0x18, 0x00, 0x00}));
}

TEST(Z21Spec, Section3_LocoAndTurnoutModeAddressesBigEndian) {
    EXPECT_EQ(onlyRequestOf<GetLocoMode>({0x06, 0x00, 0x60, 0x00, 0x01, 0x02}).address, 0x0102);
    EXPECT_EQ(onlyRequestOf<SetLocoMode>({0x07, 0x00, 0x61, 0x00, 0x00, 0x03, 0x01}),
              (SetLocoMode{3, DecoderFormat::Motorola}));
    EXPECT_EQ(onlyRequestOf<GetTurnoutMode>({0x06, 0x00, 0x70, 0x00, 0x00, 0x02}).address, 2);
    EXPECT_EQ(onlyRequestOf<SetTurnoutMode>({0x07, 0x00, 0x71, 0x00, 0x00, 0x02, 0x00}),
              (SetTurnoutMode{2, DecoderFormat::Dcc}));
    EXPECT_EQ(encodeReply(LocoMode{0x0102, DecoderFormat::Motorola}),
              (Bytes{0x07, 0x00, 0x60, 0x00, 0x01, 0x02, 0x01}));
    EXPECT_EQ(encodeReply(TurnoutMode{2, DecoderFormat::Dcc}),
              (Bytes{0x07, 0x00, 0x70, 0x00, 0x00, 0x02, 0x00}));
}

TEST(Z21Spec, Section4_1_GetLocoInfoShortAndLongAddress) {
    EXPECT_EQ(onlyRequestOf<GetLocoInfo>({0x09, 0x00, 0x40, 0x00, 0xE3, 0xF0, 0x00, 0x03, 0x10}).address, 3);
    // 1234 = 0x04D2: from 128 on the two top bits of Adr_MSB are set (0xC4) and ignored when read.
    EXPECT_EQ(onlyRequestOf<GetLocoInfo>(
                  {0x09, 0x00, 0x40, 0x00, 0xE3, 0xF0, 0xC4, 0xD2, 0xE3 ^ 0xF0 ^ 0xC4 ^ 0xD2})
                  .address,
              1234);
    EXPECT_EQ(encodeRequest(GetLocoInfo{1234}),
              (Bytes{0x09, 0x00, 0x40, 0x00, 0xE3, 0xF0, 0xC4, 0xD2, 0x05}));
}

TEST(Z21Spec, Section4_2_SetLocoDrive128StepsForward) {
    // Loco 3, 128 steps (0x13), forward, "R000 0010" = step 1.
    const auto drive =
        onlyRequestOf<SetLocoDrive>({0x0A, 0x00, 0x40, 0x00, 0xE4, 0x13, 0x00, 0x03, 0x82, 0x76});
    EXPECT_EQ(drive, (SetLocoDrive{3, {SpeedStepMode::Steps128, true, 1, false}}));
}

TEST(Z21Spec, Section4_2_SetLocoDrive28StepsBitOrder) {
    // "R00V5 VVVV": step 2 is R0010010, the fifth bit V5 carries the step's lowest bit.
    const auto drive =
        onlyRequestOf<SetLocoDrive>({0x0A, 0x00, 0x40, 0x00, 0xE4, 0x12, 0x00, 0x05, 0x12, 0xE1});
    EXPECT_EQ(drive, (SetLocoDrive{5, {SpeedStepMode::Steps28, false, 2, false}}));
}

TEST(Z21Spec, Section4_3_1_SetLocoFunctionOnOffToggle) {
    EXPECT_EQ(onlyRequestOf<SetLocoFunction>({0x0A, 0x00, 0x40, 0x00, 0xE4, 0xF8, 0x00, 0x03, 0x40, 0x5F}),
              (SetLocoFunction{3, 0, FunctionAction::On}));
    EXPECT_EQ(onlyRequestOf<SetLocoFunction>({0x0A, 0x00, 0x40, 0x00, 0xE4, 0xF8, 0x00, 0x03, 0x05, 0x1A}),
              (SetLocoFunction{3, 5, FunctionAction::Off}));
    EXPECT_EQ(onlyRequestOf<SetLocoFunction>({0x0A, 0x00, 0x40, 0x00, 0xE4, 0xF8, 0x00, 0x03, 0x9F, 0x80}),
              (SetLocoFunction{3, 31, FunctionAction::Toggle}));
}

TEST(Z21Spec, Section4_4_LocoInfoWithF0F1F12F29) {
    LocoInfo info{3, true, {SpeedStepMode::Steps128, true, 1, false}, 0, false, false};
    info.functions = (1u << 0) | (1u << 1) | (1u << 12) | (1u << 29);
    const Bytes bytes = encodeReply(info);
    // DataLen 15 (n = 8, from firmware 1.42), B = busy, KKK = 4, RVVVVVVV = 0x82, DB4 = L|J, DB5 bit 7 = F12.
    const Bytes body{0xEF, 0x00, 0x03, 0x0C, 0x82, 0x11, 0x80, 0x00, 0x00, 0x01};
    Bytes expected{0x0F, 0x00, 0x40, 0x00};
    expected.insert(expected.end(), body.begin(), body.end());
    expected.push_back(xorOf(body));
    EXPECT_EQ(bytes, expected);
    EXPECT_EQ(onlyReplyOf<LocoInfo>(bytes), info);
}

TEST(Z21Spec, Section4_4_LocoInfoWithoutDb8ReadsF29To31Off) {
    const Bytes body{0xEF, 0xC4, 0xD2, 0x02, 0x0F, 0x10, 0x00, 0x00, 0x00};
    Bytes datagram{0x0E, 0x00, 0x40, 0x00};
    datagram.insert(datagram.end(), body.begin(), body.end());
    datagram.push_back(xorOf(body));
    const LocoInfo info = onlyReplyOf<LocoInfo>(datagram);
    EXPECT_EQ(info.address, 1234);
    EXPECT_EQ(info.speed, (LocoSpeed{SpeedStepMode::Steps28, false, 27, false}));
    EXPECT_EQ(info.functions, 1u);
}

TEST(Z21Spec, Section4_5_SetLocoEmergencyStop) {
    EXPECT_EQ(onlyRequestOf<SetLocoEmergencyStop>({0x08, 0x00, 0x40, 0x00, 0x92, 0x00, 0x03, 0x91}).address,
              3);
}

TEST(Z21Spec, Section5_FigureTurnoutFiveOutputTwo) {
    // The figure of chapter 5: keyboard turnout #5 is Z21 address 4; 0x89 activates output 2, 0x81 ends it,
    // and the turnout info says 0x02 (P = 1 was switched last).
    onlyRequestOf<GetTurnoutInfo>({0x08, 0x00, 0x40, 0x00, 0x43, 0x00, 0x04, 0x47});
    EXPECT_EQ(onlyRequestOf<SetTurnout>({0x09, 0x00, 0x40, 0x00, 0x53, 0x00, 0x04, 0x89, 0xDE}),
              (SetTurnout{4, true, true, false}));
    EXPECT_EQ(onlyRequestOf<SetTurnout>({0x09, 0x00, 0x40, 0x00, 0x53, 0x00, 0x04, 0x81, 0xD6}),
              (SetTurnout{4, true, false, false}));
    EXPECT_EQ(encodeReply(TurnoutInfo{4, TurnoutPosition::Output2}),
              (Bytes{0x09, 0x00, 0x40, 0x00, 0x43, 0x00, 0x04, 0x02, 0x45}));
}

TEST(Z21Spec, Section5_2_QueueBit) {
    EXPECT_EQ(onlyRequestOf<SetTurnout>({0x09, 0x00, 0x40, 0x00, 0x53, 0x01, 0x00, 0xA8, 0xFA}),
              (SetTurnout{256, false, true, true}));
}

TEST(Z21Spec, Section1_3_ThreePacketsInOneDatagram) {
    // LAN_X_GET_TURNOUT_INFO #4, #5 and LAN_RMBUS_GETDATA #0 (which this codec does not read).
    const Bytes datagram{0x08, 0x00, 0x40, 0x00, 0x43, 0x00, 0x04, 0x47, 0x08, 0x00, 0x40,
                         0x00, 0x43, 0x00, 0x05, 0x46, 0x05, 0x00, 0x81, 0x00, 0x00};
    const DatagramRequests read = readRequests(datagram);
    EXPECT_TRUE(read.errors.empty());
    ASSERT_EQ(read.requests.size(), 3u);
    EXPECT_EQ(std::get<GetTurnoutInfo>(read.requests[0].body).address, 4);
    EXPECT_EQ(std::get<GetTurnoutInfo>(read.requests[1].body).address, 5);
    EXPECT_EQ(std::get<UnknownRequest>(read.requests[2].body), (UnknownRequest{0x81, Bytes{0x00}}));
}
