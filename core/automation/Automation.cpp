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

void Automation::start(std::chrono::milliseconds interval) {
    dispatcher_.occupancyRead(occupiedContacts());
    for (const auto& [locId, train] : dispatcher_.trains())
        dispatcher_.setMode(locId, TrainMode::Automatic, clock_());
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
        case DriveCommand::Kind::Speed:
            railway_.setSpeed(command.locId, command.speed);
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
