#include "z21/RequestCodec.h"

namespace stellwerk::z21 {

namespace {

// Each request as the packet a client sends (the specification's tables, chapters 2 to 5).
struct RequestEncoder {
    std::vector<std::uint8_t> operator()(const GetSerialNumber&) const { return PacketWriter(0x10).finish(); }
    std::vector<std::uint8_t> operator()(const GetCode&) const { return PacketWriter(0x18).finish(); }
    std::vector<std::uint8_t> operator()(const GetHardwareInfo&) const { return PacketWriter(0x1A).finish(); }
    std::vector<std::uint8_t> operator()(const Logoff&) const { return PacketWriter(0x30).finish(); }
    std::vector<std::uint8_t> operator()(const SetBroadcastFlags& r) const {
        return PacketWriter(0x50).littleEndian32(r.flags).finish();
    }
    std::vector<std::uint8_t> operator()(const GetBroadcastFlags&) const {
        return PacketWriter(0x51).finish();
    }
    std::vector<std::uint8_t> operator()(const GetSystemState&) const { return PacketWriter(0x85).finish(); }
    std::vector<std::uint8_t> operator()(const GetLocoMode& r) const {
        return PacketWriter(0x60).bigEndian16(r.address).finish();
    }
    std::vector<std::uint8_t> operator()(const SetLocoMode& r) const {
        return PacketWriter(0x61).bigEndian16(r.address).byte(std::uint8_t(r.format)).finish();
    }
    std::vector<std::uint8_t> operator()(const GetTurnoutMode& r) const {
        return PacketWriter(0x70).bigEndian16(r.address).finish();
    }
    std::vector<std::uint8_t> operator()(const SetTurnoutMode& r) const {
        return PacketWriter(0x71).bigEndian16(r.address).byte(std::uint8_t(r.format)).finish();
    }
    std::vector<std::uint8_t> operator()(const GetXVersion&) const { return x({0x21, 0x21}); }
    std::vector<std::uint8_t> operator()(const GetXStatus&) const { return x({0x21, 0x24}); }
    std::vector<std::uint8_t> operator()(const SetTrackPowerOff&) const { return x({0x21, 0x80}); }
    std::vector<std::uint8_t> operator()(const SetTrackPowerOn&) const { return x({0x21, 0x81}); }
    std::vector<std::uint8_t> operator()(const SetStop&) const { return x({0x80}); }
    std::vector<std::uint8_t> operator()(const GetFirmwareVersion&) const { return x({0xF1, 0x0A}); }
    std::vector<std::uint8_t> operator()(const GetLocoInfo& r) const {
        return x({0xE3, 0xF0, locoAddressMsb(r.address), std::uint8_t(r.address & 0xFF)});
    }
    std::vector<std::uint8_t> operator()(const SetLocoDrive& r) const {
        return x({0xE4, std::uint8_t(0x10 | driveCode(r.speed.mode)), locoAddressMsb(r.address),
                  std::uint8_t(r.address & 0xFF), speedByte(r.speed)});
    }
    std::vector<std::uint8_t> operator()(const SetLocoFunction& r) const {
        const auto db3 = std::uint8_t((std::uint8_t(r.action) << 6) | (r.function & 0x3F));
        return x({0xE4, 0xF8, locoAddressMsb(r.address), std::uint8_t(r.address & 0xFF), db3});
    }
    std::vector<std::uint8_t> operator()(const SetLocoEmergencyStop& r) const {
        return x({0x92, locoAddressMsb(r.address), std::uint8_t(r.address & 0xFF)});
    }
    std::vector<std::uint8_t> operator()(const GetTurnoutInfo& r) const {
        return x({0x43, std::uint8_t(r.address >> 8), std::uint8_t(r.address & 0xFF)});
    }
    std::vector<std::uint8_t> operator()(const SetTurnout& r) const {
        const auto db2 =
            std::uint8_t(0x80 | (r.queue ? 0x20 : 0) | (r.activate ? 0x08 : 0) | (r.secondOutput ? 1 : 0));
        return x({0x53, std::uint8_t(r.address >> 8), std::uint8_t(r.address & 0xFF), db2});
    }
    std::vector<std::uint8_t> operator()(const UnknownRequest& r) const {
        PacketWriter writer(r.header);
        for (const std::uint8_t byte : r.data)
            writer.byte(byte);
        return writer.finish();
    }

    static std::vector<std::uint8_t> x(std::initializer_list<std::uint8_t> bytes) {
        return PacketWriter(XBusHeader).bytes(bytes).finishXBus();
    }
};

} // namespace

std::vector<std::uint8_t> encodeRequest(const RequestBody& request) {
    return std::visit(RequestEncoder{}, request);
}

} // namespace stellwerk::z21
