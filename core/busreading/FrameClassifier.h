#pragma once

#include "can/CanFrame.h"
#include "ro/RoProfile.h"

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <vector>

namespace stellwerk::busreading {

// The protocols Stellwerk knows on a CAN bus: the CS2's, M-CAN, the protocol of the MS1 handhelds
// (which share the CS2's bus), OpenRailCAN (Orc) and the RO relay/IO modules' (Ro, seed 004). Foreign: a
// frame no enabled protocol claims (another program's, a device Stellwerk does not speak to, or garbage);
// it is counted and shown, never dropped. Foreign stays the last.
enum class Protocol { Cs2, Mcan, Orc, Ro, Foreign };
inline constexpr std::size_t ProtocolCount = std::size_t(Protocol::Foreign) + 1;

// The short name used in JSON and filters: "cs2", "mcan", "ro", "foreign".
std::string_view protocolName(Protocol protocol);

// What protocols are expected on one bus, in the order they are asked to claim a frame (the more
// specific first). A station's bus (also over TCP/UDP, whose gateways pass every frame): M-CAN and CS2;
// a USB-CAN adapter may add the protocols of the modules wired to it, as their codecs arrive.
class BusProfile {
public:
    BusProfile(std::initializer_list<Protocol> protocols);
    // The profile of a bus behind a CS2/CS3 or Gleisbox: MS1 handhelds may share it (M-CAN, asked first:
    // the CS2 protocol claims every 29-bit frame), and the CS2 protocol.
    static BusProfile centralStation() { return BusProfile{Protocol::Mcan, Protocol::Cs2}; }
    // A CS2's bus with OpenRailCAN devices on it (ORC notes A7): ORC asked first, since the CS2 protocol
    // claims every 29-bit frame; no MS1 handhelds.
    static BusProfile openRailCan() { return BusProfile{Protocol::Orc, Protocol::Cs2}; }

    // M-CAN's priorities overlap ORC's (notes O26): with M-CAN on the bus, ORC claims nothing, unless the
    // central hands out only bus ids with 110 in bits 9..7 (the CS2's hash marker, which M-CAN never
    // uses as cmd); then ORC claims exactly those frames. Off by default.
    BusProfile& orcOnlyWithCs2Marker(bool on) {
        orcWithMarker_ = on;
        return *this;
    }
    bool orcOnlyWithCs2Marker() const { return orcWithMarker_; }

    const std::vector<Protocol>& protocols() const { return protocols_; }
    bool expects(Protocol protocol) const;

    // An RO module on this bus. RO frames carry nothing that tells them (notes B7, C4): only the ids
    // configured here claim a frame for Ro, standard or extended, asked before every other protocol.
    BusProfile& addRoModule(const ro::FrameIds& ids);
    const std::vector<ro::FrameIds>& roModules() const { return roModules_; }

    // Which configured RO module a frame travels to or from (its index in roModules()), and which way.
    struct RoFrame {
        std::size_t module = 0;
        ro::Direction direction = ro::Direction::Request;
    };
    std::optional<RoFrame> roFrame(const can::CanFrame& frame) const;

private:
    std::vector<Protocol> protocols_;
    std::vector<ro::FrameIds> roModules_;
    bool orcWithMarker_ = false;
};

// Which protocol a frame belongs to on a bus with this profile: the first protocol of the profile that
// claims it, else Foreign. Pure: the same frame and profile always give the same answer.
Protocol classify(const can::CanFrame& frame, const BusProfile& profile);

} // namespace stellwerk::busreading
