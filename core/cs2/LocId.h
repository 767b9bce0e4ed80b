#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace stellwerk::cs2 {

// The track protocol a Loc-ID addresses, in the vocabulary of the CLI and bus monitor.
enum class Protocol : std::uint8_t {
    Mm2,
    Sx1,
    Mfx,
    Sx2,
    Dcc,
    Mm2Accessory,
    DccAccessory,
    Sx1Accessory,
    Other
};

// Every range of the document's Loc-ID table (chapter 1.3.1.2), including the reserved ones.
enum class LocIdRange : std::uint8_t {
    Mm2,                // 0x0000-0x03FF MM1/2 locos and function decoders
    Reserved,           // 0x0400, 0x0C00, 0x1400, 0x2400, 0x3400 blocks
    Sx1,                // 0x0800-0x0BFF
    Mm2FunctionDecoder, // 0x1000-0x13FF reserved for MM1/2 function decoders F1-F4
    Private,            // 0x1800-0x1BFF free for private users and clubs
    Company,            // 0x1C00-0x1FFF free for companies
    Mm2Loco20kHz,       // 0x2000-0x23FF reserved for MM1/2 loco decoders (20 kHz)
    Sx1Accessory,       // 0x2800-0x2BFF
    Traction,           // 0x2C00-0x2FFF reserved for tractions (GUI-internal ids)
    Mm2Accessory,       // 0x3000-0x33FF
    DccAccessory,       // 0x3800-0x3FFF
    Mfx,                // 0x4000-0x7FFF
    Sx2,                // 0x8000-0xBFFF
    Dcc,                // 0xC000-0xFFFF
    DeviceUid,          // above 0xFFFF: a device or mfx decoder UID, not a Loc-ID
};

std::string_view protocolName(Protocol protocol);
std::optional<Protocol> protocolFromName(std::string_view name);
std::string_view rangeName(LocIdRange range);

// A Loc-ID: the 32-bit "local id" that encodes track protocol and address in its position.
// Loco addresses count from the range base (DCC 3 = 0xC003); accessory addresses are the 1-based
// keyboard numbers users see (MM accessory 1 = 0x3000), as the CS2 keyboard and RailControl count.
class LocId {
public:
    constexpr LocId() = default;
    constexpr explicit LocId(std::uint32_t value) : value_(value) {}

    // Builds the Loc-ID for an address; nullopt when the address does not fit the protocol's range
    // (accessory numbers start at 1).
    static std::optional<LocId> fromAddress(Protocol protocol, std::uint32_t address);

    constexpr std::uint32_t value() const { return value_; }
    LocIdRange range() const;
    Protocol protocol() const;
    // Distance from the start of the range: the wire offset (0x3003 -> 3).
    std::uint32_t offset() const;
    // The address a user sees: offset for locos, offset + 1 for accessories.
    std::uint32_t address() const;
    bool isAccessory() const;

    friend constexpr bool operator==(LocId a, LocId b) { return a.value_ == b.value_; }

private:
    std::uint32_t value_ = 0;
};

} // namespace stellwerk::cs2
