// WiThrottleServer: one line of a client, answered from the railway or carried out through its throttle port.

#include "model/Railway.h"
#include "withrottleserver/WiThrottleServer.h"

namespace stellwerk::withrottleserver {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};

QString describe(const withrottle::LocoSelection& selection) {
    if (const auto* address = std::get_if<withrottle::LocoAddress>(&selection))
        return QString::fromStdString(withrottle::formatLocoAddress(*address));
    return QString::fromStdString(std::get<withrottle::RosterSelection>(selection).name);
}

} // namespace

void WiThrottleServer::handle(WiThrottleClient& client, const withrottle::ClientMessage& message) {
    std::visit(Overloaded{
                   [&](const withrottle::DeviceName& m) {
                       client.deviceName = m.name;
                       send(client, withrottle::HeartbeatInterval{heartbeatSeconds()});
                       tell(WiThrottleEvent::Kind::Named, client, QString::fromStdString(m.name));
                   },
                   [&](const withrottle::HardwareId& m) { client.hardwareId = m.id; },
                   [&](const withrottle::Heartbeat& m) {
                       if (m.kind != withrottle::HeartbeatKind::Beat)
                           client.heartbeatWatched = m.kind == withrottle::HeartbeatKind::MonitoringOn;
                   },
                   [&](const withrottle::SetPower& m) { setPower(client, m.on); },
                   [&](const withrottle::SwitchTurnout& m) { switchTurnout(client, m); },
                   [&](const withrottle::SetRoute& m) { setRoute(client, m); },
                   [&](const withrottle::Quit&) { quit(client); },
                   [&](const withrottle::AcquireLoco& m) { acquire(client, m); },
                   [&](const withrottle::ReleaseLoco& m) { release(client, m); },
                   [&](const withrottle::ThrottleAction& m) { act(client, m); },
                   [&](const withrottle::UnknownLine&) {
                       ++counters_.unknownLines;
                       ++client.unknownLines;
                   },
                   [&](const withrottle::ClientVersion&) {},
               },
               message);
}

// True while the station is heard; else the client is told why nothing happens, and nothing is kept.
bool WiThrottleServer::canDrive(WiThrottleClient& client) {
    if (railway_ && wiRailway_ && railway_->throttlePort().canDrive())
        return true;
    ++counters_.refused;
    send(client, withrottle::PowerStatus{withrottle::PowerState::Unknown});
    send(client, withrottle::ServerMessage{"The station is not heard: nothing was done."});
    tell(WiThrottleEvent::Kind::Refused, client, QStringLiteral("the station is not heard"));
    return false;
}

void WiThrottleServer::acquire(WiThrottleClient& client, const withrottle::AcquireLoco& request) {
    if (!canDrive(client))
        return;
    const std::optional<std::uint32_t> loco = wiRailway_->locoFor(request.selection);
    if (!loco) {
        send(client, withrottle::ServerMessage{"No locomotive " + describe(request.selection).toStdString()});
        return;
    }
    const QString driver = railway_->throttlePort().owners().driverOf(*loco);
    if (!driver.isEmpty() && driver != client.name() && !request.steal) {
        send(client, withrottle::ThrottleReply{request.throttle, withrottle::ThrottleReplyKind::StealNeeded,
                                               request.key});
        tell(WiThrottleEvent::Kind::StealNeeded, client,
             QStringLiteral("%1 driven by %2").arg(describe(request.selection), driver));
        return;
    }
    hold(client, request, *loco);
}

// The loco joins the throttle (taken from whoever drove it, who is told): added, labels, its state.
void WiThrottleServer::hold(WiThrottleClient& client, const withrottle::AcquireLoco& request,
                            std::uint32_t locId) {
    railway_->throttlePort().owners().take(locId, client.name());
    if (!client.holding(request.throttle, locId))
        client.throttles[request.throttle].push_back(ThrottleLoco{locId, request.key, std::nullopt});
    ThrottleLoco* loco = client.holding(request.throttle, locId);
    loco->told.reset();
    send(client,
         withrottle::ThrottleReply{request.throttle, withrottle::ThrottleReplyKind::Added, loco->key});
    send(client, withrottle::FunctionLabels{request.throttle, loco->key, wiRailway_->functionLabels(locId)});
    tellLoco(client, request.throttle, *loco);
    tell(WiThrottleEvent::Kind::Acquired, client,
         QStringLiteral("%1 (Loc-ID 0x%2)")
             .arg(describe(request.selection))
             .arg(locId, 4, 16, QLatin1Char('0')));
}

void WiThrottleServer::release(WiThrottleClient& client, const withrottle::ReleaseLoco& request) {
    for (ThrottleLoco* loco : client.locos(request.throttle, request.key)) {
        const std::uint32_t locId = loco->locId;
        const std::string key = loco->key;
        std::erase_if(client.throttles[request.throttle],
                      [&](const ThrottleLoco& held) { return held.locId == locId; });
        if (railway_ && client.holdersOf(locId).empty())
            railway_->throttlePort().owners().release(locId, client.name());
        send(client,
             withrottle::ThrottleReply{request.throttle, withrottle::ThrottleReplyKind::Removed, key});
        tell(WiThrottleEvent::Kind::Released, client, QString::fromStdString(key));
    }
}

void WiThrottleServer::act(WiThrottleClient& client, const withrottle::ThrottleAction& request) {
    const bool query = std::holds_alternative<withrottle::QuerySpeed>(request.action) ||
                       std::holds_alternative<withrottle::QueryDirection>(request.action) ||
                       std::holds_alternative<withrottle::SetSpeedStepMode>(request.action);
    const std::vector<ThrottleLoco*> locos = client.locos(request.throttle, request.key);
    if (locos.empty() || (!query && !canDrive(client)))
        return;
    for (ThrottleLoco* loco : locos)
        actOn(client, request.throttle, *loco, request.action);
}

void WiThrottleServer::actOn(WiThrottleClient& client, char throttle, ThrottleLoco& loco,
                             const withrottle::LocoAction& action) {
    model::ThrottlePort& port = railway_->throttlePort();
    const QString me = client.name();
    const auto status = [&](withrottle::LocoUpdate update) {
        send(client, withrottle::LocoStatus{throttle, loco.key, update});
    };
    const std::optional<model::LocoRun> shown = port.shown(loco.locId);
    std::visit(
        Overloaded{
            [&](const withrottle::SetSpeed& a) {
                port.setSpeed(me, loco.locId, WiThrottleRailway::systemSpeed(a.speed));
            },
            [&](const withrottle::SetDirection& a) { port.setDirection(me, loco.locId, a.forward); },
            [&](const withrottle::FunctionKey& a) { pressFunction(client, loco.locId, a); },
            [&](const withrottle::EmergencyStop&) { port.emergencyStop(me, loco.locId); },
            [&](const withrottle::Idle&) { port.setSpeed(me, loco.locId, 0); },
            [&](const withrottle::QuerySpeed&) {
                status(withrottle::SpeedState{WiThrottleRailway::throttleSpeed(shown ? shown->speed : 0)});
            },
            [&](const withrottle::QueryDirection&) {
                status(withrottle::DirectionState{!shown || shown->forward});
            },
            [&](const withrottle::SetSpeedStepMode&) { status(withrottle::SpeedStepState{1}); },
        },
        action);
}

// F1<n> pressed / F0<n> released: a momentary key is on while held, any other changes on a press; f<0|1><n>
// sets it as said.
void WiThrottleServer::pressFunction(WiThrottleClient& client, std::uint32_t locId,
                                     const withrottle::FunctionKey& key) {
    model::ThrottlePort& port = railway_->throttlePort();
    if (key.forced)
        return port.setFunction(client.name(), locId, key.function, key.pressed);
    if (wiRailway_->isMomentary(locId, key.function))
        return port.setFunction(client.name(), locId, key.function, key.pressed);
    if (!key.pressed)
        return;
    const std::optional<model::LocoRun> shown = port.shown(locId);
    const bool on = shown && ((shown->functions >> key.function) & 1u);
    port.setFunction(client.name(), locId, key.function, !on);
}

void WiThrottleServer::setPower(WiThrottleClient& client, bool on) {
    if (canDrive(client))
        railway_->throttlePort().setPower(on);
}

void WiThrottleServer::switchTurnout(WiThrottleClient& client, const withrottle::SwitchTurnout& request) {
    if (!canDrive(client))
        return;
    const std::optional<std::int64_t> keyboard = wiRailway_->turnoutOf(request.systemName);
    if (!keyboard)
        return send(client, withrottle::ServerMessage{"No turnout " + request.systemName});
    wiRailway_->switchTurnout(*keyboard, request.action);
}

void WiThrottleServer::setRoute(WiThrottleClient& client, const withrottle::SetRoute& request) {
    if (!canDrive(client))
        return;
    const std::optional<std::int64_t> route = wiRailway_->routeOf(request.systemName);
    if (!route)
        return send(client, withrottle::ServerMessage{"No route " + request.systemName});
    if (!railway_->runRoute(*route))
        send(client, withrottle::ServerMessage{"Route " + request.systemName + " cannot be set now"});
}

void WiThrottleServer::quit(WiThrottleClient& client) {
    goAway(client, WiThrottleEvent::Kind::Quit);
}

} // namespace stellwerk::withrottleserver
