#include "sim/StationHandhelds.h"

#include "cs2/Codec.h"
#include "cs2/Hash.h"
#include "cs2/Request.h"
#include "mcan/Codec.h"
#include "sim/SimulatedStation.h"

namespace stellwerk::sim {
namespace {

// The UID the station's handheld side commands the station with (its own hash, never the station's).
constexpr std::uint32_t HandheldSideUid = 0x4D534D31; // "MSM1"

mcanhandhelds::RailFormat formatOf(cs2config::LocomotiveDecoder decoder) {
    using Decoder = cs2config::LocomotiveDecoder;
    switch (decoder) {
    case Decoder::Mfx:
        return mcanhandhelds::RailFormat::Mfx;
    case Decoder::Dcc:
        return mcanhandhelds::RailFormat::Dcc;
    case Decoder::None:
    case Decoder::Unknown:
        return mcanhandhelds::RailFormat::Unknown;
    default:
        return mcanhandhelds::RailFormat::Motorola;
    }
}

} // namespace

StationHandhelds::StationHandhelds(SimulatedStation& station, mcanhandhelds::MasterSettings settings,
                                   QObject* parent)
    : QObject(parent), station_(station), hash_(cs2::hashFromUid(HandheldSideUid)) {
    settings.uid = station_.uid(); // the handhelds see the CS2's UID in the stage-0 reply
    master_ = std::make_unique<mcanhandhelds::HandheldMaster>(
        [this](const std::vector<can::CanFrame>& frames) { emit framesEmitted(frames); }, settings, this);
    master_->setBook(&book_);
    master_->setRailway(this);
}

StationHandhelds::~StationHandhelds() {
    master_->setRailway(nullptr);
}

void StationHandhelds::receive(const can::CanFrame& frame) {
    if (mcan::isMcan(frame))
        master_->receive({frame});
    else
        observe(frame);
}

// What the station reports on the bus: a locomotive's speed, direction or function, the track power.
void StationHandhelds::observe(const can::CanFrame& frame) {
    if (!frame.extended || !cs2::isResponse(frame))
        return;
    const cs2::DecodeResult result = cs2::decode(frame);
    if (!result)
        return;
    std::visit(
        [this](const auto& message) {
            using T = std::decay_t<decltype(message)>;
            if constexpr (std::is_same_v<T, cs2::LocoSpeed> || std::is_same_v<T, cs2::LocoDirection> ||
                          std::is_same_v<T, cs2::LocoFunction>)
                master_->locoChanged(message.loco.value());
            else if constexpr (std::is_same_v<T, cs2::SystemStop> || std::is_same_v<T, cs2::SystemGo> ||
                               std::is_same_v<T, cs2::SystemHalt>)
                master_->powerChanged();
            else if constexpr (std::is_same_v<T, cs2::Overload>)
                master_->shortCircuitReported();
        },
        result.value().body);
}

std::vector<mcanhandhelds::HandheldLoco> StationHandhelds::locomotives() const {
    std::vector<mcanhandhelds::HandheldLoco> locos;
    for (const cs2config::Locomotive& record : station_.layout().locomotives().locomotives) {
        if (record.uid == 0)
            continue;
        mcanhandhelds::HandheldLoco loco{record.uid,
                                         record.name,
                                         mcanhandhelds::kindOfSymbol(record.symbol),
                                         formatOf(record.decoder),
                                         {}};
        for (const cs2config::Function& function : record.functions)
            if (function.number >= 0 && function.icon != 0)
                loco.functions.push_back(
                    {function.number, function.trigger() == cs2config::FunctionTrigger::Momentary});
        locos.push_back(std::move(loco));
    }
    return locos;
}

std::optional<mcanhandhelds::LocoDrive> StationHandhelds::drive(std::uint32_t locId) const {
    const SimulatedLoco* loco = station_.loco(locId);
    if (!loco)
        return mcanhandhelds::LocoDrive{};
    mcanhandhelds::LocoDrive drive{loco->speed, loco->direction != 2, 0};
    for (std::size_t f = 0; f < loco->functions.size(); ++f)
        if (loco->functions[f])
            drive.functions |= 1u << f;
    return drive;
}

std::optional<bool> StationHandhelds::powerOn() const {
    return station_.power() != TrackPower::Stopped;
}

// The handhelds' intents become the station's own commands, with the handheld side's hash.
void StationHandhelds::command(can::CanFrame frame) {
    frame.id = (frame.id & ~0xFFFFu) | hash_;
    station_.receive(frame);
}

void StationHandhelds::setSpeed(std::uint32_t locId, int speed) {
    command(cs2::encode(cs2::request(cs2::LocoSpeed{cs2::LocId(locId), std::uint16_t(speed)})));
}

void StationHandhelds::setDirection(std::uint32_t locId, bool forward) {
    command(cs2::encode(cs2::request(cs2::LocoDirection{cs2::LocId(locId), std::uint8_t(forward ? 1 : 2)})));
}

void StationHandhelds::setFunction(std::uint32_t locId, int function, bool on) {
    command(cs2::encode(cs2::request(
        cs2::LocoFunction{cs2::LocId(locId), std::uint8_t(function), std::uint8_t(on ? 1 : 0), {}})));
}

void StationHandhelds::setPower(bool on) {
    if (on)
        command(cs2::encode(cs2::request(cs2::SystemGo{0})));
    else
        command(cs2::encode(cs2::request(cs2::SystemStop{0})));
}

} // namespace stellwerk::sim
