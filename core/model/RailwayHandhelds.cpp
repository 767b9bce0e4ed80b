#include "model/RailwayHandhelds.h"

#include "mcanhandhelds/HandheldMaster.h"
#include "model/Railway.h"

namespace stellwerk::model {
namespace {

mcanhandhelds::RailFormat formatOf(cs2::Protocol protocol) {
    switch (protocol) {
    case cs2::Protocol::Mfx:
        return mcanhandhelds::RailFormat::Mfx;
    case cs2::Protocol::Dcc:
        return mcanhandhelds::RailFormat::Dcc;
    case cs2::Protocol::Mm2:
        return mcanhandhelds::RailFormat::Motorola;
    default:
        break;
    }
    return mcanhandhelds::RailFormat::Unknown;
}

} // namespace

RailwayHandhelds::RailwayHandhelds(Railway& railway, mcanhandhelds::HandheldMaster& master, QObject* parent)
    : QObject(parent), railway_(railway), master_(master) {
    connect(&railway_, &Railway::loaded, this, [this] { master_.locomotivesChanged(); });
    connect(&railway_, &Railway::locomotivesChanged, this, [this](const QList<quint32>& ids) {
        for (const quint32 id : ids)
            master_.locoChanged(id);
    });
    // A handheld's intent the station did not confirm: it shows the locomotive as the station has it again.
    connect(&railway_, &Railway::locomotiveCommandFailed, this,
            [this](quint32 loco) { master_.locoChanged(loco); });
    connect(&railway_, &Railway::powerChanged, this, [this] { master_.powerChanged(); });
    connect(&railway_, &Railway::overloaded, this, [this] { master_.shortCircuitReported(); });
    connect(&railway_, &Railway::stateReportedChanged, this, [this] { master_.powerChanged(); });
    master_.setRailway(this);
}

RailwayHandhelds::~RailwayHandhelds() {
    master_.setRailway(nullptr);
}

// lokomotive.cs2 keeps the MS1's symbol (`.symbol`: 0 electric, 1 diesel, 2 steam, 3 none).
mcanhandhelds::LocoKind RailwayHandhelds::kindOf(std::uint32_t locId) const {
    const cs2config::LocomotiveFile* file = railway_.locomotiveFile();
    if (!file)
        return mcanhandhelds::LocoKind::None;
    for (const cs2config::Locomotive& record : file->locomotives)
        if (record.uid == locId)
            return mcanhandhelds::kindOfSymbol(record.symbol);
    return mcanhandhelds::LocoKind::None;
}

std::vector<mcanhandhelds::HandheldLoco> RailwayHandhelds::locomotives() const {
    std::vector<mcanhandhelds::HandheldLoco> locos;
    for (const Locomotive& loco : railway_.state().locomotives().items()) {
        if (!loco.inLayout())
            continue; // seen on the bus, not in lokomotive.cs2: another controller's
        mcanhandhelds::HandheldLoco shown{loco.id().value(),
                                          loco.displayName().toStdString(),
                                          kindOf(loco.id().value()),
                                          formatOf(loco.protocol()),
                                          {}};
        for (const LocomotiveFunction& function : loco.functions())
            shown.functions.push_back(
                {function.number, function.trigger == cs2config::FunctionTrigger::Momentary});
        locos.push_back(std::move(shown));
    }
    return locos;
}

// As the railway shows it (the handhelds' display follows the railway's last values).
std::optional<mcanhandhelds::LocoDrive> RailwayHandhelds::drive(std::uint32_t locId) const {
    const std::optional<LocoRun> run = railway_.throttlePort().shown(locId);
    if (!run)
        return std::nullopt;
    return mcanhandhelds::LocoDrive{run->speed, run->forward, run->functions};
}

std::optional<bool> RailwayHandhelds::powerOn() const {
    return railway_.throttlePort().powerOn();
}

void RailwayHandhelds::setSpeed(std::uint32_t locId, int speed) {
    railway_.throttlePort().setSpeed(ThrottlePort::handhelds(), locId, speed);
}

void RailwayHandhelds::setDirection(std::uint32_t locId, bool forward) {
    railway_.throttlePort().setDirection(ThrottlePort::handhelds(), locId, forward);
}

void RailwayHandhelds::setFunction(std::uint32_t locId, int function, bool on) {
    railway_.throttlePort().setFunction(ThrottlePort::handhelds(), locId, function, on);
}

void RailwayHandhelds::setPower(bool on) {
    railway_.throttlePort().setPower(on);
}

} // namespace stellwerk::model
