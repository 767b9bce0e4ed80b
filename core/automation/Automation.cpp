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
}

Automation::~Automation() = default;

std::optional<std::string> Automation::place(std::uint32_t locId, std::int64_t contact,
                                             trackgraph::End towards, int lengthMm) {
    const model::Locomotive* loco = railway_.locomotive(locId);
    const std::string name = loco ? loco->displayName().toStdString()
                                  : QStringLiteral("0x%1").arg(locId, 4, 16, QLatin1Char('0')).toStdString();
    std::optional<std::string> problem = dispatcher_.place(locId, name, lengthMm, contact, towards);
    carryOut();
    return problem;
}

std::optional<std::string> Automation::placeInBlock(std::uint32_t locId, int block, trackgraph::End towards,
                                                    int lengthMm) {
    const model::Locomotive* loco = railway_.locomotive(locId);
    const std::string name = loco ? loco->displayName().toStdString()
                                  : QStringLiteral("0x%1").arg(locId, 4, 16, QLatin1Char('0')).toStdString();
    std::optional<std::string> problem = dispatcher_.placeInBlock(locId, name, lengthMm, block, towards);
    carryOut();
    return problem;
}

void Automation::remove(std::uint32_t locId) {
    dispatcher_.remove(locId);
    told_.erase(locId);
    carryOut();
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
        return;
    }
    dispatcher_.occupancyRead(occupiedContacts());
    carryOut();
}

// A speed or direction command of this program (the desk, an MS1, an OpenRailCAN throttle) that is not
// the automation's own.
void Automation::commandSent(quint32 loco, int control) {
    using Control = model::Railway::LocomotiveControl;
    if (commanding_ || control == int(Control::Function))
        return;
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
        if (!train || !loco || train->mode != TrainMode::Automatic || heardOwnCommand(id, *loco))
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
    if (heard == told.unheard.end())
        return loco.speed() == told.speed || loco.speed() == told.heard; // or a command of ours failed
    told.unheard.erase(told.unheard.begin(), heard + 1);
    told.heard = loco.speed();
    return true;
}

// The locomotive turned the other way, as the automation tells it: the station stops it as well, so the
// speed to hear is 0.
void Automation::reverse(std::uint32_t locId) {
    const model::Locomotive* loco = railway_.locomotive(locId);
    if (!loco)
        return;
    Told& told = told_[locId];
    told.turnedFrom = loco->direction();
    told.direction =
        loco->direction() == cs2::Direction::Forward ? cs2::Direction::Backward : cs2::Direction::Forward;
    told.speed = 0;
    told.unheard.push_back(0);
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
            told.unheard.push_back(command.speed);
            if (told.unheard.size() > 8)
                told.unheard.pop_front();
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
