#include "sim/DeviceService.h"

#include "cs2/Hash.h"

namespace stellwerk::sim {
namespace {

constexpr std::size_t PacketBytes = 8;

} // namespace

DeviceService::DeviceService(StationState& state, const StationIdentity& identity)
    : state_(state), identity_(identity), station_(StatusChannels::centralStation(identity.uid)) {
    if (identity.gleisboxUid)
        gleisbox_ = StatusChannels::gleisbox(*identity.gleisboxUid);
}

bool DeviceService::handle(const cs2::Message& m, Outbox& out) {
    if (const auto* request = std::get_if<cs2::Ping>(&m.body))
        return ping(*request, m, out), true;
    if (const auto* request = std::get_if<cs2::StatusDataConfig>(&m.body))
        return describe(*request, m, out), true;
    if (const auto* request = std::get_if<cs2::SystemStatus>(&m.body))
        return status(*request, m, out), true;
    return false;
}

void DeviceService::ping(const cs2::Ping&, const cs2::Message& m, Outbox& out) {
    out.respond(
        cs2::Ping{cs2::DeviceIdentity{identity_.uid, VersionMajor, VersionMinor, identity_.deviceType}},
        m.prio);
    if (identity_.gleisboxUid)
        out.respond(cs2::Ping{cs2::DeviceIdentity{*identity_.gleisboxUid, 1, 39, GleisboxType}}, m.prio);
}

// 6.2 and field notes: the index's bytes in DLC-8 packets with the response bit and the packet
// number in the hash (0x0301 first), then the end frame with the device's hash and the count. An
// index the device does not have gets the end frame with no packets.
void DeviceService::describe(const cs2::StatusDataConfig& request, const cs2::Message& m, Outbox& out) {
    StatusChannels* channels = channelsOf(request.device);
    if (!channels || request.form != cs2::StatusDataConfig::Form::Request)
        return;
    const auto bytes = channels->indexBytes(request.index).value_or(std::vector<std::uint8_t>{});
    std::uint16_t packets = 0;
    for (std::size_t at = 0; at < bytes.size(); at += PacketBytes) {
        cs2::StatusDataConfig packet;
        packet.form = cs2::StatusDataConfig::Form::Packet;
        packet.packet.size = PacketBytes;
        for (std::size_t i = 0; i < PacketBytes && at + i < bytes.size(); ++i)
            packet.packet.bytes[i] = bytes[at + i];
        out.add(cs2::encode(cs2::Message{m.prio, true, cs2::hashFromPacketNumber(++packets), packet}));
    }
    cs2::StatusDataConfig end;
    end.form = cs2::StatusDataConfig::Form::End;
    end.device = request.device;
    end.index = request.index;
    end.packetCount = std::uint8_t(packets);
    out.respond(end, m.prio);
}

// 2.12: a read (DLC 6) is answered with the value (DLC 8), or with the request itself when the
// channel does not exist; a configuration write (DLC 8) with accepted/rejected (DLC 7). A broadcast
// read is answered by the station with the address as asked.
void DeviceService::status(const cs2::SystemStatus& request, const cs2::Message& m, Outbox& out) {
    StatusChannels* channels = request.device == 0 ? &station_ : channelsOf(request.device);
    if (!channels || request.accepted)
        return;
    cs2::SystemStatus answer{request.device, request.channel, std::nullopt, std::nullopt};
    if (request.value) {
        answer.accepted = channels->configure(request.channel, *request.value);
        out.respond(answer, m.prio);
        watchLoad(out); // a lower current limit may already be passed
        return;
    }
    answer.value = channels->reading(request.channel, mainTrackAmpere());
    if (!answer.value)
        answer.value = channels->setting(request.channel);
    out.respond(answer, m.prio);
}

void DeviceService::watchLoad(Outbox& out) {
    if (loadMa_ <= station_.currentLimitMa() || state_.power == TrackPower::Stopped)
        return;
    state_.power = TrackPower::Stopped;
    out.respond(cs2::Overload{identity_.uid, station_.mainTrackChannel()});
    out.respond(cs2::SystemStop{identity_.uid}); // the track is off: every listener sees STOP
}

double DeviceService::mainTrackAmpere() const {
    return state_.power == TrackPower::Stopped ? 0.0 : loadMa_ / 1000.0;
}

StatusChannels* DeviceService::channelsOf(std::uint32_t device) {
    if (device == identity_.uid)
        return &station_;
    if (gleisbox_ && identity_.gleisboxUid && device == *identity_.gleisboxUid)
        return &*gleisbox_;
    return nullptr;
}

} // namespace stellwerk::sim
