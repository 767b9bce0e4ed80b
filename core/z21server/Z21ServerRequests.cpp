// Z21Server: one request of a client, answered from the railway or carried out through its throttle port.

#include "model/Railway.h"
#include "z21server/Z21Server.h"

namespace stellwerk::z21server {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};

bool isLoco(const z21::RequestBody& body) {
    return std::holds_alternative<z21::GetLocoInfo>(body) ||
           std::holds_alternative<z21::SetLocoDrive>(body) ||
           std::holds_alternative<z21::SetLocoFunction>(body) ||
           std::holds_alternative<z21::SetLocoEmergencyStop>(body) ||
           std::holds_alternative<z21::GetLocoMode>(body) || std::holds_alternative<z21::SetLocoMode>(body);
}

bool isTurnout(const z21::RequestBody& body) {
    return std::holds_alternative<z21::GetTurnoutInfo>(body) ||
           std::holds_alternative<z21::SetTurnout>(body) ||
           std::holds_alternative<z21::GetTurnoutMode>(body) ||
           std::holds_alternative<z21::SetTurnoutMode>(body);
}

bool isPower(const z21::RequestBody& body) {
    return std::holds_alternative<z21::SetTrackPowerOn>(body) ||
           std::holds_alternative<z21::SetTrackPowerOff>(body) || std::holds_alternative<z21::SetStop>(body);
}

} // namespace

void Z21Server::handle(Z21Client& client, const z21::Request& request) {
    ++counters_.requests;
    ++client.requests;
    client.lastRequestAt = QDateTime::currentDateTime();
    client.lastRequest = describeRequest(request.body);
    if (request.wrongChecksum) {
        ++counters_.wrongChecksums;
        ++client.wrongChecksums;
    }
    if (isLoco(request.body))
        onLoco(client, request.body);
    else if (isTurnout(request.body))
        onTurnout(client, request.body);
    else if (isPower(request.body))
        onPower(client, request.body);
    else
        answer(client, request.body);
}

// The requests about the central itself, answered at once.
void Z21Server::answer(Z21Client& client, const z21::RequestBody& body) {
    const std::uint8_t state = z21Railway_ ? z21Railway_->centralState() : z21::central::TrackVoltageOff;
    std::visit(
        Overloaded{
            [&](const z21::GetSerialNumber&) { send(client, z21::SerialNumber{options_.serialNumber}); },
            [&](const z21::GetCode&) { send(client, z21::FeatureCode{0}); },
            [&](const z21::GetHardwareInfo&) { send(client, z21::HardwareInfo{}); },
            [&](const z21::GetFirmwareVersion&) { send(client, z21::FirmwareVersion{}); },
            [&](const z21::GetXVersion&) { send(client, z21::XVersion{}); },
            [&](const z21::GetXStatus&) { send(client, z21::XStatusChanged{state}); },
            [&](const z21::SetBroadcastFlags& r) { client.flags = r.flags; },
            [&](const z21::GetBroadcastFlags&) { send(client, z21::BroadcastFlags{client.flags}); },
            [&](const z21::GetSystemState&) {
                z21::SystemState system = z21Railway_ ? z21Railway_->systemState() : z21::SystemState{};
                system.centralState = state;
                send(client, system);
            },
            [&](const z21::Logoff&) {
                if (const std::optional<Z21Client> gone = clients_.remove(client.name()))
                    goAway(*gone, Z21Event::Kind::LoggedOff);
            },
            [&](const auto&) { unknown(client); },
        },
        body);
}

void Z21Server::onLoco(Z21Client& client, const z21::RequestBody& body) {
    std::visit(Overloaded{
                   [&](const z21::GetLocoInfo& r) {
                       const z21::SpeedStepMode mode = client.follows(r.address)
                                                           ? client.subscription(r.address)->mode
                                                           : z21::SpeedStepMode::Steps128;
                       client.subscribe(r.address, mode);
                       sendLocoInfo(client, r.address);
                   },
                   [&](const z21::SetLocoDrive& r) { drive(client, r); },
                   [&](const z21::SetLocoFunction& r) { function(client, r); },
                   [&](const z21::SetLocoEmergencyStop& r) { emergencyStop(client, r.address); },
                   [&](const z21::GetLocoMode& r) {
                       const auto format =
                           z21Railway_ ? z21Railway_->locoFormat(r.address) : z21::DecoderFormat::Dcc;
                       send(client, z21::LocoMode{r.address, format});
                   },
                   [&](const auto&) {}, // SetLocoMode: the station knows each decoder's format
               },
               body);
}

void Z21Server::onTurnout(Z21Client& client, const z21::RequestBody& body) {
    std::visit(Overloaded{
                   [&](const z21::GetTurnoutInfo& r) {
                       send(client,
                            z21Railway_ ? z21Railway_->turnoutInfo(r.address) : z21::TurnoutInfo{r.address});
                   },
                   [&](const z21::SetTurnout& r) {
                       if (!r.activate)
                           return; // the station ends the switching itself after the article's time
                       if (!railway_ || !railway_->throttlePort().canDrive())
                           return refuse(client, 0);
                       z21Railway_->switchTurnout(r.address, r.secondOutput);
                   },
                   [&](const z21::GetTurnoutMode& r) {
                       const auto format =
                           z21Railway_ ? z21Railway_->turnoutFormat(r.address) : z21::DecoderFormat::Motorola;
                       send(client, z21::TurnoutMode{r.address, format});
                   },
                   [&](const auto&) {}, // SetTurnoutMode: the station's articles say their format
               },
               body);
}

void Z21Server::onPower(Z21Client& client, const z21::RequestBody& body) {
    if (!railway_ || !railway_->throttlePort().canDrive())
        return refuse(client, 0);
    model::ThrottlePort& port = railway_->throttlePort();
    if (std::holds_alternative<z21::SetTrackPowerOn>(body)) {
        port.setPower(true);
    } else {
        port.setPower(false); // the CS2's STOP is its one way to stop every locomotive at once
        if (std::holds_alternative<z21::SetStop>(body))
            broadcast(z21::broadcast::DrivingAndSwitching, z21::Stopped{});
    }
}

// The locomotive on a Z21 address, when it can be driven now; else the client is answered and nullopt.
std::optional<std::uint32_t> Z21Server::drivable(Z21Client& client, std::uint16_t address) {
    const std::optional<std::uint32_t> loco = z21Railway_ ? z21Railway_->locoAt(address) : std::nullopt;
    if (!loco) {
        unknown(client);
        return std::nullopt;
    }
    if (!railway_->throttlePort().canDrive()) {
        refuse(client, address);
        return std::nullopt;
    }
    return loco;
}

void Z21Server::drive(Z21Client& client, const z21::SetLocoDrive& request) {
    client.subscribe(request.address, request.speed.mode);
    const std::optional<std::uint32_t> loco = drivable(client, request.address);
    if (!loco)
        return;
    model::ThrottlePort& port = railway_->throttlePort();
    const QString me = client.name();
    const bool firstTime = port.owners().driverOf(*loco) != me;
    if (request.speed.emergencyStop) {
        port.emergencyStop(me, *loco);
    } else {
        const std::optional<model::LocoRun> shown = port.shown(*loco);
        if (shown && shown->forward != request.speed.forward)
            port.setDirection(me, *loco, request.speed.forward);
        port.setSpeed(me, *loco, z21::systemSpeed(request.speed));
    }
    if (firstTime)
        tell(Z21Event::Kind::Drove, client, request.address,
             QStringLiteral("Loc-ID 0x%1").arg(*loco, 4, 16, QLatin1Char('0')));
}

void Z21Server::function(Z21Client& client, const z21::SetLocoFunction& request) {
    client.subscribe(request.address, client.follows(request.address)
                                          ? client.subscription(request.address)->mode
                                          : z21::SpeedStepMode::Steps128);
    const std::optional<std::uint32_t> loco = drivable(client, request.address);
    if (!loco)
        return;
    model::ThrottlePort& port = railway_->throttlePort();
    bool on = request.action == z21::FunctionAction::On;
    if (request.action == z21::FunctionAction::Toggle) {
        const std::optional<model::LocoRun> shown = port.shown(*loco);
        on = !(shown && (shown->functions >> request.function) & 1u);
    }
    port.setFunction(client.name(), *loco, request.function, on);
}

void Z21Server::emergencyStop(Z21Client& client, std::uint16_t address) {
    if (const std::optional<std::uint32_t> loco = drivable(client, address))
        railway_->throttlePort().emergencyStop(client.name(), *loco);
}

// Not carried out and not kept for later: the client is told the track power is off (the Z21 protocol's
// way of saying nothing can be driven now).
void Z21Server::refuse(Z21Client& client, std::uint16_t address) {
    ++counters_.refused;
    send(client, z21::TrackPowerOff{});
    tell(Z21Event::Kind::Refused, client, address, QStringLiteral("the station is not heard"));
}

void Z21Server::unknown(Z21Client& client) {
    ++counters_.unknown;
    send(client, z21::UnknownCommand{});
}

} // namespace stellwerk::z21server
