#include "station/StationUpdates.h"

namespace stellwerk::station {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

cs2::Direction directionOf(std::uint8_t value) {
    return value <= 3 ? cs2::Direction(value) : cs2::Direction::Keep;
}

} // namespace

bool StationUpdates::empty() const {
    return speeds.empty() && directions.empty() && functions.empty() && accessories.empty() &&
           contacts.empty() && power.empty() && overloads.empty() && readings.empty() && devices.empty() &&
           automation.empty() && discoveries.empty() && !configurationChanged;
}

void StationUpdates::clear() {
    speeds.clear();
    directions.clear();
    functions.clear();
    accessories.clear();
    contacts.clear();
    power.clear();
    overloads.clear();
    readings.clear();
    devices.clear();
    automation.clear();
    discoveries.clear();
    configurationChanged = false;
}

void StationEventCollector::observe(const cs2::Message& message) {
    auto& u = updates_;
    const bool answer = message.response;
    std::visit(Overloaded{
                   [&](const cs2::LocoSpeed& m) {
                       if (answer && m.speed)
                           u.speeds.push_back({m.loco, *m.speed});
                   },
                   [&](const cs2::LocoDirection& m) {
                       if (answer && m.direction)
                           u.directions.push_back({m.loco, directionOf(*m.direction)});
                   },
                   [&](const cs2::LocoFunction& m) {
                       if (answer && m.value)
                           u.functions.push_back({m.loco, m.function, *m.value});
                   },
                   [&](const cs2::AccessorySwitch& m) {
                       if (answer)
                           u.accessories.push_back({m.article, m.position, m.current});
                   },
                   [&](const cs2::S88Event& m) {
                       if (m.change)
                           u.contacts.push_back({m.device, m.contact, m.change->newState != 0,
                                                 m.change->oldState != 0, m.change->time10ms});
                   },
                   [&](const cs2::Ping& m) {
                       if (answer && m.identity)
                           u.devices.push_back(*m.identity);
                   },
                   [&](const cs2::LocoDiscovery& m) {
                       if (answer)
                           u.discoveries.push_back(m);
                   },
                   [&](const cs2::AutomationSwitch& m) {
                       if (!answer)
                           return;
                       AutomationAnnouncement a{m.device, m.function, std::nullopt, m.loco};
                       if (!m.loco)
                           a.state = m.position;
                       u.automation.push_back(a);
                   },
                   [&](const cs2::ConfigDataStream& m) {
                       if (m.form == cs2::ConfigDataStream::Form::BroadcastHeader)
                           u.configurationChanged = true;
                   },
                   [&](const auto&) { observeSystem(message); },
               },
               message.body);
}

void StationEventCollector::observeSystem(const cs2::Message& message) {
    if (!message.response)
        return;
    auto& u = updates_;
    std::visit(Overloaded{
                   [&](const cs2::SystemStop& m) {
                       u.power.push_back({m.target, PowerState::Stopped});
                   },
                   [&](const cs2::SystemGo& m) {
                       u.power.push_back({m.target, PowerState::Running});
                   },
                   [&](const cs2::SystemHalt& m) {
                       u.power.push_back({m.target, PowerState::Halted});
                   },
                   [&](const cs2::Overload& m) {
                       u.overloads.push_back({m.sender, m.channel});
                   },
                   [&](const cs2::SystemStatus& m) {
                       if (m.value && !m.accepted)
                           u.readings.push_back({m.device, m.channel, *m.value});
                   },
                   [&](const auto&) {},
               },
               message.body);
}

} // namespace stellwerk::station
