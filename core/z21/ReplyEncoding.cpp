#include "z21/ReplyCodec.h"

namespace stellwerk::z21 {

namespace {

std::vector<std::uint8_t> x(std::initializer_list<std::uint8_t> bytes) {
    return PacketWriter(XBusHeader).bytes(bytes).finishXBus();
}

std::vector<std::uint8_t> systemState(const SystemState& s) {
    return PacketWriter(0x84)
        .littleEndian16(std::uint16_t(s.mainCurrent))
        .littleEndian16(std::uint16_t(s.programmingCurrent))
        .littleEndian16(std::uint16_t(s.filteredMainCurrent))
        .littleEndian16(std::uint16_t(s.temperature))
        .littleEndian16(s.supplyVoltage)
        .littleEndian16(s.trackVoltage)
        .bytes({s.centralState, s.centralStateEx, 0, s.capabilities})
        .finish();
}

// DB4 0DSLFGHJ: D double traction, S smart search, L = F0, F..J = F4..F1 (4.4).
std::uint8_t functionByte(const LocoInfo& info) {
    return std::uint8_t((info.doubleTraction ? 0x40 : 0) | (info.smartSearch ? 0x20 : 0) |
                        ((info.functions & 1u) << 4) | ((info.functions >> 1) & 0x0F));
}

std::vector<std::uint8_t> locoInfo(const LocoInfo& info) {
    const auto db2 = std::uint8_t((info.busy ? 0x08 : 0) | infoCode(info.speed.mode));
    return x({0xEF, locoAddressMsb(info.address), std::uint8_t(info.address & 0xFF), db2,
              speedByte(info.speed), functionByte(info), std::uint8_t(info.functions >> 5),
              std::uint8_t(info.functions >> 13), std::uint8_t(info.functions >> 21),
              std::uint8_t((info.functions >> 29) & 0x07)});
}

struct ReplyEncoder {
    std::vector<std::uint8_t> operator()(const SerialNumber& r) const {
        return PacketWriter(0x10).littleEndian32(r.serial).finish();
    }
    std::vector<std::uint8_t> operator()(const FeatureCode& r) const {
        return PacketWriter(0x18).byte(r.code).finish();
    }
    std::vector<std::uint8_t> operator()(const HardwareInfo& r) const {
        return PacketWriter(0x1A).littleEndian32(r.hardwareType).littleEndian32(r.firmware).finish();
    }
    std::vector<std::uint8_t> operator()(const BroadcastFlags& r) const {
        return PacketWriter(0x51).littleEndian32(r.flags).finish();
    }
    std::vector<std::uint8_t> operator()(const SystemState& r) const { return systemState(r); }
    std::vector<std::uint8_t> operator()(const LocoMode& r) const {
        return PacketWriter(0x60).bigEndian16(r.address).byte(std::uint8_t(r.format)).finish();
    }
    std::vector<std::uint8_t> operator()(const TurnoutMode& r) const {
        return PacketWriter(0x70).bigEndian16(r.address).byte(std::uint8_t(r.format)).finish();
    }
    std::vector<std::uint8_t> operator()(const XVersion& r) const {
        return x({0x63, 0x21, r.xBusVersion, r.commandStationId});
    }
    std::vector<std::uint8_t> operator()(const XStatusChanged& r) const {
        return x({0x62, 0x22, r.centralState});
    }
    std::vector<std::uint8_t> operator()(const TrackPowerOff&) const { return x({0x61, 0x00}); }
    std::vector<std::uint8_t> operator()(const TrackPowerOn&) const { return x({0x61, 0x01}); }
    std::vector<std::uint8_t> operator()(const ProgrammingMode&) const { return x({0x61, 0x02}); }
    std::vector<std::uint8_t> operator()(const TrackShortCircuit&) const { return x({0x61, 0x08}); }
    std::vector<std::uint8_t> operator()(const UnknownCommand&) const { return x({0x61, 0x82}); }
    std::vector<std::uint8_t> operator()(const Stopped&) const { return x({0x81, 0x00}); }
    std::vector<std::uint8_t> operator()(const FirmwareVersion& r) const {
        return x({0xF3, 0x0A, std::uint8_t(r.version >> 8), std::uint8_t(r.version & 0xFF)});
    }
    std::vector<std::uint8_t> operator()(const LocoInfo& r) const { return locoInfo(r); }
    std::vector<std::uint8_t> operator()(const TurnoutInfo& r) const {
        return x(
            {0x43, std::uint8_t(r.address >> 8), std::uint8_t(r.address & 0xFF), std::uint8_t(r.position)});
    }
};

} // namespace

std::vector<std::uint8_t> encodeReply(const Reply& reply) {
    return std::visit(ReplyEncoder{}, reply);
}

} // namespace stellwerk::z21
