#include "automation/Automation.h"

#include "model/Railway.h"

#include <algorithm>
#include <chrono>

namespace stellwerk::automation {

namespace {

trackgraph::ContactKey graphKey(quint32 key) {
    return {std::int64_t(key >> 16), std::int64_t(key & 0xFFFF)};
}

Automation::Clock steadyClock() {
    return [start = std::chrono::steady_clock::now()] {
        return Millis(
            std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start)
                .count());
    };
}

} // namespace

Automation::Automation(model::Railway& railway, const trackgraph::TrackGraph& graph,
                       Dispatcher::Options options, QObject* parent)
    : QObject(parent), railway_(railway), dispatcher_(graph, options), clock_(steadyClock()) {
    connect(&timer_, &QTimer::timeout, this, &Automation::tick);
    connect(&railway_, &model::Railway::contactsChanged, this, &Automation::contactsChanged);
    connect(&railway_, &model::Railway::accessoriesChanged, this, &Automation::accessoriesChanged);
    connect(&railway_, &model::Railway::switchingEnded, this,
            [this](qint64 address, int position, bool acknowledged) {
                switchings_ = std::max(0, switchings_ - 1);
                dispatcher_.turnoutSwitched(address, position, acknowledged, clock_());
                carryOut();
            });
    connect(&railway_, &model::Railway::powerChanged, this, [this](station::PowerState state) {
        if (state != station::PowerState::Running && !dispatcher_.paused()) {
            dispatcher_.halt("STOP");
            carryOut();
        }
    });
    connect(&railway_, &model::Railway::stateReportedChanged, this, &Automation::stateReportedChanged);
    connect(&railway_, &model::Railway::locomotiveCommandSent, this,
            [this](quint32 loco, model::Railway::LocomotiveControl control, int) {
                commandSent(loco, int(control));
            });
    connect(&railway_, &model::Railway::locomotivesChanged, this, &Automation::locomotivesChanged);
    connect(&railway_, &model::Railway::stateCorrected, this, &Automation::corrected);
    connect(&railway_, &model::Railway::locomotiveCommandAcknowledged, this,
            [this](quint32 loco, model::Railway::LocomotiveControl control, int) {
                if (control == model::Railway::LocomotiveControl::Speed)
                    speedAnswered(loco, true);
            });
    connect(&railway_, &model::Railway::locomotiveCommandFailed, this,
            [this](quint32 loco, model::Railway::LocomotiveControl control, int, const QString&) {
                if (control == model::Railway::LocomotiveControl::Speed)
                    speedAnswered(loco, false);
            });
}

Automation::~Automation() = default;

std::optional<std::string> Automation::place(std::uint32_t locId, std::int64_t contact,
                                             trackgraph::End towards, int lengthMm) {
    std::optional<std::string> problem =
        dispatcher_.place(locId, trainName(locId), lengthMm, contact, towards);
    carryOut();
    return problem;
}

std::optional<std::string> Automation::placeInBlock(std::uint32_t locId, int block, trackgraph::End towards,
                                                    int lengthMm) {
    std::optional<std::string> problem =
        dispatcher_.placeInBlock(locId, trainName(locId), lengthMm, block, towards);
    carryOut();
    return problem;
}

bool Automation::remove(std::uint32_t locId) {
    const bool removed = dispatcher_.remove(locId);
    carryOut();
    told_.erase(locId);
    return removed;
}

std::string Automation::trainName(std::uint32_t locId) const {
    const model::Locomotive* loco = railway_.locomotive(locId);
    return loco ? loco->displayName().toStdString()
                : QStringLiteral("0x%1").arg(locId, 4, 16, QLatin1Char('0')).toStdString();
}

void Automation::run(std::chrono::milliseconds interval) {
    dispatcher_.occupancyRead(occupiedContacts());
    if (const auto power = railway_.power(); power && *power != station::PowerState::Running)
        dispatcher_.halt("the track power is off");
    carryOut();
    if (interval.count() > 0)
        timer_.start(interval);
}

void Automation::stopByHand(std::uint32_t locId, const std::string& by) {
    dispatcher_.takenByHand(locId, by);
    commanding_ = true;
    railway_.setSpeed(locId, 0);
    commanding_ = false;
    carryOut();
}

void Automation::stopAtNextStop() {
    dispatcher_.stopAtNextStop(clock_());
    carryOut();
}

void Automation::start(std::chrono::milliseconds interval) {
    dispatcher_.occupancyRead(occupiedContacts());
    for (const auto& [locId, train] : dispatcher_.trains()) {
        if (const model::Locomotive* loco = railway_.locomotive(locId))
            told_[locId] = Told{{}, loco->speed(), loco->speed(), loco->direction(), std::nullopt};
        dispatcher_.setMode(locId, TrainMode::Automatic, clock_());
    }
    carryOut();
    if (interval.count() > 0)
        timer_.start(interval);
}

void Automation::tick() {
    dispatcher_.tick(clock_());
    carryOut();
}

void Automation::resume() {
    dispatcher_.resume(clock_());
    carryOut();
}

void Automation::handBack(std::uint32_t locId) {
    if (const model::Locomotive* loco = railway_.locomotive(locId))
        told_[locId] = Told{{}, loco->speed(), loco->speed(), loco->direction(), std::nullopt};
    dispatcher_.handBack(locId, clock_());
    carryOut();
}

void Automation::finish() {
    timer_.stop();
    dispatcher_.finish();
    carryOut();
}

void Automation::contactsChanged(const QList<quint32>& keys) {
    for (const quint32 key : keys) {
        const model::FeedbackContact* contact = railway_.contact(key);
        if (!contact || !contact->known())
            continue;
        auto [known, added] = occupied_.try_emplace(key, !contact->occupied());
        if (!added && known->second == contact->occupied())
            continue;
        known->second = contact->occupied();
        dispatcher_.contactChanged(graphKey(key), contact->occupied(), clock_());
    }
    carryOut();
}

void Automation::accessoriesChanged(const QList<qint64>& ids) {
    for (const qint64 id : ids)
        if (const model::Accessory* accessory = railway_.accessory(id);
            accessory && accessory->isPositionReported())
            dispatcher_.turnoutReported(id, accessory->position(), clock_());
    carryOut();
}

void Automation::stateReportedChanged(bool reported) {
    if (!reported) {
        dispatcher_.stationLost();
        carryOut(); // the events; no command is sent to a silent station
        return;
    }
    dispatcher_.occupancyRead(occupiedContacts());
    dispatcher_.stationBack();
    carryOut();
}

// A speed or direction command of this program (the desk, an MS1, an OpenRailCAN throttle) that is not
// the automation's own.
void Automation::commandSent(quint32 loco, int control) {
    using Control = model::Railway::LocomotiveControl;
    if (commanding_ && control == int(Control::Speed))
        told_[loco].unheard.push_back(told_[loco].speed); // sent: its answer is to come
    if (commanding_ || control == int(Control::Function))
        return;
    if (const auto correction = correcting_.find({loco, control}); correction != correcting_.end()) {
        if (--correction->second == 0)
            correcting_.erase(correction);
        return;
    }
    const Train* train = dispatcher_.train(loco);
    if (!train || train->mode != TrainMode::Automatic)
        return;
    dispatcher_.takenByHand(loco, "a throttle");
    carryOut();
}

// A speed or direction the station confirmed that the automation did not send: another controller on the
// bus drives the locomotive.
void Automation::locomotivesChanged(const QList<quint32>& ids) {
    for (const quint32 id : ids) {
        const Train* train = dispatcher_.train(id);
        const model::Locomotive* loco = railway_.locomotive(id);
        if (!train || !loco || train->mode != TrainMode::Automatic)
            continue;
        if (train->state == TrainState::Unknown || train->state == TrainState::Lost) {
            // What the station says after an outage is where things stand (a station started again has
            // forgotten every speed), not another controller; it is what to hear from now on.
            told_[id] = Told{{}, loco->speed(), loco->speed(), loco->direction(), std::nullopt};
            continue;
        }
        if (heardOwnCommand(id, *loco))
            continue;
        dispatcher_.takenByHand(id, "another controller");
    }
    carryOut();
}

bool Automation::heardOwnCommand(std::uint32_t locId, const model::Locomotive& loco) {
    Told& told = told_[locId];
    if (loco.isDirectionReported() && told.direction) {
        if (loco.direction() == *told.direction)
            told.turnedFrom.reset();
        else if (loco.direction() != told.turnedFrom)
            return false;
    }
    if (!loco.isSpeedReported())
        return true;
    const auto heard = std::find(told.unheard.begin(), told.unheard.end(), int(loco.speed()));
    // The answer to a command of ours may have come (and left the list) before the change it made is
    // heard: a train braking when STOP came hears its creep speed after the stop was sent.
    if (heard == told.unheard.end())
        return loco.speed() == told.speed || loco.speed() == told.heard;
    told.unheard.erase(told.unheard.begin(), heard + 1);
    told.heard = loco.speed();
    return true;
}

// The railway brings a locomotive back to what the station last confirmed after a command it did not
// confirm (announced just before it is sent): the command that follows is the railway's, not a person's
// throttle, and the speed it sends is one to hear back.
void Automation::corrected(const model::Correction& correction) {
    using Kind = model::CommandTarget::Kind;
    using Control = model::Railway::LocomotiveControl;
    if (!correction.sentValue ||
        (correction.target.kind != Kind::Speed && correction.target.kind != Kind::Direction))
        return;
    const auto locId = std::uint32_t(correction.target.id);
    const bool speed = correction.target.kind == Kind::Speed;
    ++correcting_[{locId, int(speed ? Control::Speed : Control::Direction)}];
    if (!speed || !told_.contains(locId))
        return;
    Told& told = told_[locId];
    told.speed = *correction.sentValue;
    told.unheard.push_back(*correction.sentValue);
}

// The station's answer to the oldest speed command waiting for one: confirmed, it is the speed it has
// now; not confirmed, it keeps the last one it confirmed, which is then ours to hear. A confirmed speed
// that is neither one still waiting nor the last one sent is somebody else's, even when it equals one
// sent long ago (another program stopping the train right after it departed, both answers in one batch).
void Automation::speedAnswered(std::uint32_t locId, bool confirmed) {
    const auto found = told_.find(locId);
    if (found == told_.end() || found->second.unheard.empty())
        return;
    Told& told = found->second;
    if (confirmed)
        told.heard = told.unheard.front();
    told.unheard.pop_front();
    if (!confirmed && told.unheard.empty())
        told.speed = told.heard;
}

// The locomotive turned the other way, as the automation tells it: the station stops it as well, so the
// speed to hear is 0 (no speed command of ours waits for that answer).
void Automation::reverse(std::uint32_t locId) {
    const model::Locomotive* loco = railway_.locomotive(locId);
    if (!loco)
        return;
    Told& told = told_[locId];
    told.turnedFrom = loco->direction();
    told.direction =
        loco->direction() == cs2::Direction::Forward ? cs2::Direction::Backward : cs2::Direction::Forward;
    told.speed = 0;
    commanding_ = true;
    railway_.setDirection(locId, *told.direction);
    commanding_ = false;
}

std::set<trackgraph::ContactKey> Automation::occupiedContacts() {
    std::set<trackgraph::ContactKey> occupied;
    occupied_.clear();
    for (const model::FeedbackContact& contact : railway_.state().contacts().items()) {
        if (!contact.known())
            continue;
        occupied_[contact.key()] = contact.occupied();
        if (contact.occupied())
            occupied.insert(graphKey(contact.key()));
    }
    return occupied;
}

// The dispatcher's commands go to the railway, its events to whoever listens.
void Automation::carryOut() {
    for (const DriveCommand& command : dispatcher_.takeCommands()) {
        switch (command.kind) {
        case DriveCommand::Kind::Speed: {
            Told& told = told_[command.locId];
            told.speed = command.speed;
            commanding_ = true;
            railway_.setSpeed(command.locId, command.speed);
            commanding_ = false;
            break;
        }
        case DriveCommand::Kind::Reverse:
            reverse(command.locId);
            break;
        case DriveCommand::Kind::Switch:
            ++switchings_;
            railway_.switchAccessory(command.article, command.position);
            break;
        case DriveCommand::Kind::PowerOff:
            railway_.stop();
            break;
        }
    }
    for (const AutomationEvent& event : dispatcher_.takeEvents())
        emit happened(event);
}

} // namespace stellwerk::automation
