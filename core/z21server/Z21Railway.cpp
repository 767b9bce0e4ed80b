#include "z21server/Z21Railway.h"

#include "model/Railway.h"
#include "model/Z21Addresses.h"

#include <cmath>

namespace stellwerk::z21server {
namespace {

// A reading scaled into mA, mV or °C from the unit its device describes.
std::int32_t scaled(const model::StatusChannel& channel, double factorForBaseUnit) {
    const std::optional<double> value = channel.value();
    if (!value)
        return 0;
    const QString unit = channel.unit().trimmed();
    const bool milli = unit.startsWith(QLatin1String("m"), Qt::CaseSensitive);
    return std::int32_t(std::lround(*value * (milli ? 1.0 : factorForBaseUnit)));
}

bool isMainCurrent(const QString& name) {
    return name == QLatin1String("HGL") || name == QLatin1String("TRACK") || name == QLatin1String("MAIN");
}

} // namespace

Z21Railway::Z21Railway(model::Railway& railway, model::Z21Addresses& addresses)
    : railway_(railway), addresses_(addresses) {}

std::vector<std::uint32_t> Z21Railway::locIds() const {
    std::vector<std::uint32_t> ids;
    for (const model::Locomotive& loco : railway_.state().locomotives().items())
        ids.push_back(loco.id().value());
    return ids;
}

void Z21Railway::coverLocomotives() {
    addresses_.cover(locIds());
}

std::optional<std::uint32_t> Z21Railway::locoAt(std::uint16_t address) const {
    return addresses_.locoAt(address, locIds());
}

std::optional<std::uint16_t> Z21Railway::addressOf(std::uint32_t locId) const {
    return addresses_.addressOf(locId);
}

z21::LocoInfo Z21Railway::locoInfo(std::uint16_t address, z21::SpeedStepMode mode, bool busy) const {
    z21::LocoInfo info;
    info.address = address;
    info.busy = busy;
    info.speed.mode = mode;
    const std::optional<std::uint32_t> loco = locoAt(address);
    const std::optional<model::LocoRun> run = loco ? railway_.throttlePort().shown(*loco) : std::nullopt;
    if (!run)
        return info;
    info.speed.forward = run->forward;
    info.speed.step = z21::stepForSystemSpeed(mode, std::uint16_t(std::clamp(run->speed, 0, 1000)));
    info.functions = run->functions;
    return info;
}

z21::DecoderFormat Z21Railway::locoFormat(std::uint16_t address) const {
    const std::optional<std::uint32_t> loco = locoAt(address);
    if (loco && cs2::LocId(*loco).protocol() == cs2::Protocol::Mm2)
        return z21::DecoderFormat::Motorola;
    return z21::DecoderFormat::Dcc;
}

z21::TurnoutInfo Z21Railway::turnoutInfo(std::uint16_t z21Number) const {
    const std::int64_t keyboard = std::int64_t(z21Number) + 1;
    z21::TurnoutInfo info{z21Number, z21::TurnoutPosition::NotSwitched};
    std::optional<int> position;
    if (const model::Accessory* accessory = railway_.accessory(keyboard)) {
        if (accessory->isPositionReported())
            position = accessory->position();
    } else {
        position = railway_.addressPosition(keyboard);
    }
    if (position)
        info.position = *position == 0 ? z21::TurnoutPosition::Output1 : z21::TurnoutPosition::Output2;
    return info;
}

z21::DecoderFormat Z21Railway::turnoutFormat(std::uint16_t z21Number) const {
    const model::Accessory* accessory = railway_.accessory(std::int64_t(z21Number) + 1);
    return accessory && accessory->isDcc() ? z21::DecoderFormat::Dcc : z21::DecoderFormat::Motorola;
}

void Z21Railway::switchTurnout(std::uint16_t z21Number, bool secondOutput) {
    const std::int64_t keyboard = std::int64_t(z21Number) + 1;
    const int position = secondOutput ? 1 : 0;
    if (railway_.accessory(keyboard))
        railway_.switchAccessory(keyboard, position);
    else
        railway_.switchAddress(keyboard, position);
}

std::uint8_t Z21Railway::centralState() const {
    const std::optional<station::PowerState> power =
        railway_.isStateReported() ? railway_.power() : std::nullopt;
    if (!power || *power == station::PowerState::Stopped)
        return z21::central::TrackVoltageOff;
    return *power == station::PowerState::Halted ? z21::central::EmergencyStop : std::uint8_t(0);
}

z21::SystemState Z21Railway::systemState() const {
    z21::SystemState state;
    for (const model::Device& device : railway_.state().devices().items()) {
        for (const model::StatusChannel& channel : device.channels()) {
            const QString name = channel.name().trimmed().toUpper();
            if (isMainCurrent(name) && state.mainCurrent == 0)
                state.mainCurrent = std::int16_t(scaled(channel, 1000.0));
            else if ((name == QLatin1String("PGL") || name == QLatin1String("PROG")) &&
                     !state.programmingCurrent)
                state.programmingCurrent = std::int16_t(scaled(channel, 1000.0));
            else if (name == QLatin1String("VOLT") && state.trackVoltage == 0)
                state.trackVoltage = std::uint16_t(std::max(0, scaled(channel, 1000.0)));
            else if (name == QLatin1String("TEMP") && state.temperature == 0)
                state.temperature = std::int16_t(scaled(channel, 1.0));
        }
    }
    state.filteredMainCurrent = state.mainCurrent;
    state.supplyVoltage = state.trackVoltage;
    state.centralState = centralState();
    return state;
}

} // namespace stellwerk::z21server
