#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace stellwerk::orccentral {

// One OpenRailCAN device the central knows: its UID, the bus id it was given, type and version, whether it
// answers, and what it last reported (inputs of an encoder, overloads of a booster).
struct OrcDevice {
    enum class State : std::uint8_t {
        Assigning,  // told its new bus id (Stellwerk's extension), waiting for its confirmation
        Online,     // answers under its bus id
        Offline,    // missed its pings; an announcement or a ping answer brings it back
        Unassigned, // did not confirm the new bus id: it shares its identifier with another device
    };
    std::uint32_t uid = 0;
    std::uint16_t busId = 0;
    std::uint8_t type = 0;
    std::uint16_t version = 0;
    State state = State::Assigning;
    int missedPings = 0;
    bool pingOutstanding = false;
    std::uint32_t inputs = 0;                       // encoders: bit n = input n
    std::uint8_t inputCount = 0;                    // encoders: 0 until it reported
    std::map<std::uint8_t, std::uint8_t> overloads; // port (0xFF: the device as a whole) -> kind 1, 2, ...
};

// The central's list of devices and its bus-id rule (001 §Bus ID Vergabe, notes A3.2): a device asks for the
// low 16 bits of its UID; when another UID, a reserved id (a legacy device of the layout) or the central
// itself has it, the central counts up to the first free one. Pure C++.
class DeviceRegistry {
public:
    explicit DeviceRegistry(std::uint16_t centralBusId);

    // An id no device may get: a legacy device configured in the layout (MM2 turnout 5 = 0x3005, ...).
    void reserve(std::uint16_t busId) { reserved_.insert(busId); }

    OrcDevice* byUid(std::uint32_t uid);
    OrcDevice* byBusId(std::uint16_t busId);
    const std::vector<OrcDevice>& devices() const { return devices_; }

    // The bus id the device with this UID has, or gets: its own if it is known, else the first free one from
    // the low 16 bits of its UID up. Empty when every id is taken.
    std::optional<std::uint16_t> busIdFor(std::uint32_t uid) const;
    // Adds the device, or gives a known one a new bus id and type.
    OrcDevice& enter(std::uint32_t uid, std::uint16_t busId, std::uint8_t type);

private:
    bool taken(std::uint16_t busId, std::uint32_t uid) const;

    std::uint16_t central_;
    std::set<std::uint16_t> reserved_;
    std::vector<OrcDevice> devices_;
};

} // namespace stellwerk::orccentral
