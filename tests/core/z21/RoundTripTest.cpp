// Every request and every reply the codec knows, written and read back to the same value.
#include "Z21TestSupport.h"

using namespace stellwerk::z21;
using namespace stellwerk::z21::test;

namespace {

std::vector<RequestBody> everyRequest() {
    std::vector<RequestBody> all;
    all.push_back(GetSerialNumber{});
    all.push_back(GetCode{});
    all.push_back(GetHardwareInfo{});
    all.push_back(Logoff{});
    all.push_back(SetBroadcastFlags{0x00010101});
    all.push_back(GetBroadcastFlags{});
    all.push_back(GetSystemState{});
    all.push_back(GetLocoMode{16383});
    all.push_back(SetLocoMode{80, DecoderFormat::Motorola});
    all.push_back(GetTurnoutMode{1023});
    all.push_back(SetTurnoutMode{0, DecoderFormat::Motorola});
    all.push_back(GetXVersion{});
    all.push_back(GetXStatus{});
    all.push_back(SetTrackPowerOff{});
    all.push_back(SetTrackPowerOn{});
    all.push_back(SetStop{});
    all.push_back(GetFirmwareVersion{});
    all.push_back(GetLocoInfo{127});
    all.push_back(GetLocoInfo{128});
    all.push_back(SetLocoDrive{10239, {SpeedStepMode::Steps14, false, 7, false}});
    all.push_back(SetLocoDrive{3, {SpeedStepMode::Steps28, true, 0, true}});
    all.push_back(SetLocoDrive{200, {SpeedStepMode::Steps128, true, 126, false}});
    all.push_back(SetLocoFunction{3, 28, FunctionAction::Toggle});
    all.push_back(SetLocoFunction{1000, 0, FunctionAction::Off});
    all.push_back(SetLocoEmergencyStop{4711});
    all.push_back(GetTurnoutInfo{65535});
    all.push_back(SetTurnout{0, false, false, false});
    all.push_back(SetTurnout{511, true, true, true});
    all.push_back(UnknownRequest{0x40, Bytes{0x24, 0x12, 0x00, 0x1C, 0x05, 0x2F}});
    return all;
}

const std::vector<RequestBody> EveryRequest = everyRequest();

std::vector<Reply> everyReply() {
    std::vector<Reply> all;
    all.push_back(SerialNumber{0xDEADBEEF});
    all.push_back(FeatureCode{0x02});
    all.push_back(HardwareInfo{});
    all.push_back(BroadcastFlags{0x00000100});
    all.push_back(SystemState{1200, -1, 1100, 41, 20000, 18500, central::ShortCircuit,
                              central::ShortCircuitInternal, 0x33});
    all.push_back(LocoMode{255, DecoderFormat::Motorola});
    all.push_back(TurnoutMode{256, DecoderFormat::Dcc});
    all.push_back(XVersion{});
    all.push_back(XStatusChanged{0x22});
    all.push_back(TrackPowerOff{});
    all.push_back(TrackPowerOn{});
    all.push_back(ProgrammingMode{});
    all.push_back(TrackShortCircuit{});
    all.push_back(UnknownCommand{});
    all.push_back(Stopped{});
    all.push_back(FirmwareVersion{0x0143});
    all.push_back(LocoInfo{9999, false, {SpeedStepMode::Steps14, false, 13, false}, 0xFFFFFFFF, true, true});
    all.push_back(LocoInfo{1, true, {SpeedStepMode::Steps28, true, 0, true}, 0x12345678, false, false});
    all.push_back(TurnoutInfo{1, TurnoutPosition::Output1});
    all.push_back(TurnoutInfo{2, TurnoutPosition::Invalid});
    return all;
}

const std::vector<Reply> EveryReply = everyReply();

} // namespace

TEST(Z21RoundTrip, EveryRequestReadsBackAsItself) {
    for (const RequestBody& body : EveryRequest) {
        const Bytes bytes = encodeRequest(body);
        EXPECT_EQ(bytes[0] | (bytes[1] << 8), int(bytes.size()));
        EXPECT_EQ(onlyRequest(bytes), (Request{body, false})) << "variant index " << body.index();
    }
}

TEST(Z21RoundTrip, EveryReplyReadsBackAsItself) {
    for (const Reply& reply : EveryReply) {
        const Bytes bytes = encodeReply(reply);
        EXPECT_EQ(bytes[0] | (bytes[1] << 8), int(bytes.size()));
        const DatagramReplies read = readReplies(bytes);
        ASSERT_EQ(read.replies.size(), 1u) << "variant index " << reply.index();
        EXPECT_EQ(read.replies[0], reply) << "variant index " << reply.index();
    }
}

TEST(Z21RoundTrip, AllRepliesInOneDatagram) {
    Bytes datagram;
    for (const Reply& reply : EveryReply) {
        const Bytes bytes = encodeReply(reply);
        datagram.insert(datagram.end(), bytes.begin(), bytes.end());
    }
    ASSERT_LE(datagram.size(), MaxDatagramSize);
    EXPECT_EQ(readReplies(datagram).replies, EveryReply);
}

TEST(Z21RoundTrip, XBusRepliesCarryTheirXor) {
    for (const Reply& reply : EveryReply) {
        const Bytes bytes = encodeReply(reply);
        if (bytes[2] == 0x40) {
            EXPECT_EQ(xorOf(std::span(bytes).subspan(4)), 0) << "variant index " << reply.index();
        }
    }
}
