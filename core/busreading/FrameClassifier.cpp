#include "busreading/FrameClassifier.h"

#include "mcan/Codec.h"
#include "orc/Codec.h"

#include <algorithm>

namespace stellwerk::busreading {

namespace {

// The CS2 protocol (document 1.2) uses 29-bit identifiers only; which command the frame carries is
// the codec's business (an unknown command is still a CS2 frame the monitor shows as such).
bool claimsCs2(const can::CanFrame& frame) {
    return frame.extended;
}

// OpenRailCAN (ORC notes A7, C4): ID24 set and priority not 00. Beside M-CAN only with the CS2 marker in
// bits 9..7 of the bus id, if the profile allows it (notes O26); else M-CAN's reading wins.
bool claimsOrc(const can::CanFrame& frame, const BusProfile& profile) {
    if (!orc::isOrc(frame))
        return false;
    return !profile.expects(Protocol::Mcan) ||
           (profile.orcOnlyWithCs2Marker() && mcan::hasCs2Marker(frame.id));
}

bool claims(Protocol protocol, const can::CanFrame& frame, const BusProfile& profile) {
    switch (protocol) {
    case Protocol::Cs2:
        return claimsCs2(frame);
    case Protocol::Mcan:
        return mcan::isMcan(frame); // notes B§6.2: no CS2 marker, and the bus-busy frame or prio bits set
    case Protocol::Orc:
        return claimsOrc(frame, profile);
    case Protocol::Ro:
        return profile.roFrame(frame).has_value(); // notes C4: the configured ids only
    case Protocol::Foreign:
        return false;
    }
    return false;
}

} // namespace

std::string_view protocolName(Protocol protocol) {
    switch (protocol) {
    case Protocol::Cs2:
        return "cs2";
    case Protocol::Mcan:
        return "mcan";
    case Protocol::Orc:
        return "orc";
    case Protocol::Ro:
        return "ro";
    case Protocol::Foreign:
        return "foreign";
    }
    return "foreign";
}

BusProfile::BusProfile(std::initializer_list<Protocol> protocols) : protocols_(protocols) {}

bool BusProfile::expects(Protocol protocol) const {
    return std::find(protocols_.begin(), protocols_.end(), protocol) != protocols_.end();
}

BusProfile& BusProfile::addRoModule(const ro::FrameIds& ids) {
    roModules_.push_back(ids);
    if (!expects(Protocol::Ro))
        protocols_.insert(protocols_.begin(), Protocol::Ro);
    return *this;
}

std::optional<BusProfile::RoFrame> BusProfile::roFrame(const can::CanFrame& frame) const {
    for (std::size_t module = 0; module < roModules_.size(); ++module)
        if (const auto direction = ro::directionOf(frame, roModules_[module]))
            return RoFrame{module, *direction};
    return std::nullopt;
}

Protocol classify(const can::CanFrame& frame, const BusProfile& profile) {
    for (const Protocol protocol : profile.protocols())
        if (claims(protocol, frame, profile))
            return protocol;
    return Protocol::Foreign;
}

} // namespace stellwerk::busreading
