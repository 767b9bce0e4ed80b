#include "model/Railway.h"

#include "model/CommandProblem.h"
#include "model/Commands.h"
#include "station/StationSession.h"

#include <QPointer>
#include <algorithm>

namespace stellwerk::model {
namespace {

template <class Key, class Out = Key>
QList<Out> toList(const ChangedKeys<Key>& keys) {
    QList<Out> list;
    list.reserve(qsizetype(keys.keys().size()));
    for (const Key& key : keys.keys())
        list.push_back(Out(key));
    return list;
}

} // namespace

Railway::Railway(station::StationSession& session, QObject* parent)
    : QObject(parent), session_(session), poller_(new ReadingPoller(session, this)),
      programmer_(new Programmer(session, this)), blockStates_(new BlockStates(session, this)),
      throttlePort_(new ThrottlePort(*this, this)) {
    connect(&session_, &station::StationSession::updated, this, &Railway::apply);
    connect(&session_.liveness(), &station::Liveness::stationSilent, this, &Railway::contactLost);
    // Before the session cancels the commands that were waiting: their failures arrive at a model that
    // already knows why.
    connect(&session_, &station::StationSession::connectionLost, this, &Railway::contactLost);
    connect(&session_.transport(), &transport::Transport::stateChanged, this,
            [this](transport::Transport::State state) {
                if (state != transport::Transport::State::Connected)
                    contactLost();
            });
    connect(poller_, &ReadingPoller::readingMissed, this, &Railway::readingMissed);
    connect(&session_, &station::StationSession::answersHeard, this, &Railway::answersHeard);
}

Railway::Railway(station::StationSession& session, const station::StartupResult& startup, QObject* parent)
    : Railway(session, parent) {
    load(startup);
}

Railway::~Railway() {
    for (auto& [id, runner] : runners_)
        runner->disconnect(this);
}

void Railway::load(const station::StartupResult& startup) {
    state_.load(startup);
    updatePollerSources();
    if (!poller_->sources().empty())
        poller_->start();
    emit loaded();
    setStateReported(stationHeard());
    for (const CommandTarget target : unconfirmed_.targets())
        checkReport(target); // the start-up's answers may show a late copy carried out
}

bool Railway::stationHeard() const {
    return session_.transport().state() == transport::Transport::State::Connected &&
           !session_.liveness().isStationSilent();
}

void Railway::contactLost() {
    const bool wasReported = stateReported_;
    state_.forgetReported();
    for (const auto& [id, runner] : std::map(runners_))
        cancelRoute(id);
    setStateReported(false);
    if (wasReported)
        announceAllUnreported();
}

// One signal per kind naming everything, so that views grey out what they show.
void Railway::announceAllUnreported() {
    RailwayChanges changes;
    for (const Locomotive& loco : state_.locomotives().items())
        changes.locomotives.add(loco.id().value());
    for (const Accessory& accessory : state_.accessories().items())
        changes.accessories.add(accessory.id());
    for (const FeedbackContact& contact : state_.contacts().items())
        changes.contacts.add(contact.key());
    announce(changes);
}

void Railway::setStateReported(bool reported) {
    if (stateReported_ == reported)
        return;
    stateReported_ = reported;
    emit stateReportedChanged(reported);
}

void Railway::replaceLocomotiveFile(const cs2config::LocomotiveFile& file) {
    state_.replaceLocomotiveFile(file);
    emit loaded();
}

void Railway::updatePollerSources() {
    std::vector<ReadingSource> sources;
    for (const Device& device : state_.devices().items())
        for (const StatusChannel& channel : device.channels())
            sources.push_back({device.uid(), channel.channel()});
    poller_->setSources(std::move(sources));
}

void Railway::apply(const station::StationUpdates& updates) {
    if (switcher_ && !updates.contacts.empty()) {
        station::StationUpdates own = updates; // a contact a device input lights is the device's alone
        std::erase_if(own.contacts, [this](const station::FeedbackContactChange& change) {
            return switcher_->lights(contactKey(change.device, change.contact));
        });
        const RailwayChanges changes = state_.apply(own, QDateTime::currentDateTime());
        announce(changes);
        return checkReports(changes);
    }
    const RailwayChanges changes = state_.apply(updates, QDateTime::currentDateTime());
    announce(changes);
    checkReports(changes);
}

void Railway::reportOccupant(ContactKey key, std::uint32_t locId) {
    announce(state_.setOccupant(key, locId));
}

void Railway::reportDevicePosition(std::int64_t accessory, std::optional<int> position) {
    announce(state_.reportDevicePosition(accessory, position));
}

void Railway::reportDeviceContact(ContactKey key, std::optional<bool> occupied) {
    announce(state_.reportDeviceContact(key, occupied, QDateTime::currentDateTime()));
}

void Railway::announce(const RailwayChanges& changes) {
    if (!changes.locomotives.empty())
        emit locomotivesChanged(toList<std::uint32_t, quint32>(changes.locomotives));
    if (!changes.accessories.empty())
        emit accessoriesChanged(toList<std::int64_t, qint64>(changes.accessories));
    if (!changes.addresses.empty())
        emit addressesChanged(toList<std::int64_t, qint64>(changes.addresses));
    if (!changes.contacts.empty())
        emit contactsChanged(toList<ContactKey, quint32>(changes.contacts));
    announceTiles(changes);
    if (!changes.devices.empty())
        emit devicesChanged(toList<std::uint32_t, quint32>(changes.devices));
    if (changes.power)
        emit powerChanged(*changes.power);
    if (changes.configurationChanged)
        emit configurationChanged();
    for (const station::OverloadReport& overload : changes.overloads) {
        emit overloaded(overload.device, overload.channel);
        const Device* device = state_.devices().find(overload.device);
        emit problem(QStringLiteral("Overload on %1 (channel %2): the track power is off")
                         .arg(device ? device->name()
                                     : QStringLiteral("0x%1").arg(overload.device, 8, 16, QLatin1Char('0')))
                         .arg(overload.channel));
    }
}

void Railway::announceTiles(const RailwayChanges& changes) {
    QList<TileRef> tiles;
    for (const std::int64_t id : changes.accessories.keys())
        for (const TileRef& tile : layout().tilesOfAccessory(id))
            tiles.push_back(tile);
    for (const ContactKey key : changes.contacts.keys())
        for (const TileRef& tile : layout().tilesOfContact(key))
            tiles.push_back(tile);
    if (!tiles.isEmpty())
        emit tilesChanged(tiles);
}

void Railway::readingMissed(quint32 uid, quint8 number) {
    Device* device = state_.devices().find(uid);
    StatusChannel* channel = device ? device->channel(number) : nullptr;
    if (channel && channel->markStale())
        emit devicesChanged({uid});
}

void Railway::locoCommand(std::uint32_t loco, LocomotiveControl control, int function, int value,
                          const cs2::Message& message, const QString& what, std::function<void()> done) {
    QPointer<Railway> self(this);
    const CommandTarget target = control == LocomotiveControl::Direction ? CommandTarget::direction(loco)
                                 : control == LocomotiveControl::Function
                                     ? CommandTarget::function(loco, function)
                                     : CommandTarget::speed(loco);
    const std::optional<int> confirmed = reportedValue(target);
    emit locomotiveCommandSent(loco, control, function);
    session_.request(message, [self, loco, control, function, value, target, confirmed, what,
                               done = std::move(done)](const station::CommandResult& result) {
        if (!self)
            return;
        self->recordOutcome(target, value, confirmed, result);
        if (!result.succeeded()) {
            emit self->locomotiveCommandFailed(loco, control, function, failureReason(result));
            emit self->problem(commandProblem(what, result));
            return;
        }
        if (done)
            done();
        emit self->locomotiveCommandAcknowledged(loco, control, function);
    });
}

void Railway::powerCommand(bool on, const cs2::Message& message, const QString& what) {
    QPointer<Railway> self(this);
    const std::optional<int> confirmed = reportedValue(CommandTarget::power());
    session_.request(message, [self, on, confirmed, what](const station::CommandResult& result) {
        if (!self)
            return;
        self->recordOutcome(CommandTarget::power(), on ? 1 : 0, confirmed, result);
        if (!result.succeeded())
            emit self->problem(commandProblem(what, result));
    });
}

QString Railway::locoName(std::uint32_t loco) const {
    const Locomotive* found = locomotive(loco);
    return found ? found->displayName() : Locomotive(cs2::LocId(loco)).displayName();
}

void Railway::setSpeed(std::uint32_t loco, int speed) {
    const auto value = std::uint16_t(std::clamp(speed, 0, int(Locomotive::MaxSpeed)));
    locoCommand(loco, LocomotiveControl::Speed, -1, value, commands::speed(cs2::LocId(loco), value),
                QStringLiteral("%1: speed %2").arg(locoName(loco)).arg(value));
}

void Railway::setDirection(std::uint32_t loco, cs2::Direction direction) {
    const QString what =
        QStringLiteral("%1: direction %2")
            .arg(locoName(loco), direction == cs2::Direction::Backward ? QStringLiteral("backward")
                                                                       : QStringLiteral("forward"));
    QPointer<Railway> self(this);
    locoCommand(loco, LocomotiveControl::Direction, -1, direction == cs2::Direction::Backward ? 1 : 0,
                commands::direction(cs2::LocId(loco), direction), what, [self, loco, direction] {
                    // The station stopped the locomotive and will not say so (field notes).
                    if (self && self->state_.locomotives().find(loco) &&
                        self->state_.locomotives().find(loco)->directionSet(direction))
                        emit self->locomotivesChanged({loco});
                });
}

void Railway::reverse(std::uint32_t loco) {
    const Locomotive* found = locomotive(loco);
    const bool forward = !found || found->direction() == cs2::Direction::Forward;
    setDirection(loco, forward ? cs2::Direction::Backward : cs2::Direction::Forward);
}

void Railway::setFunction(std::uint32_t loco, int function, bool on) {
    if (function < 0 || function >= Locomotive::MaxFunctions) {
        emit problem(QStringLiteral("%1: there is no function F%2").arg(locoName(loco)).arg(function));
        return;
    }
    locoCommand(loco, LocomotiveControl::Function, function, on ? 1 : 0,
                commands::function(cs2::LocId(loco), std::uint8_t(function), on),
                QStringLiteral("%1: F%2 %3").arg(locoName(loco)).arg(function).arg(on ? "on" : "off"));
}

void Railway::toggleFunction(std::uint32_t loco, int function) {
    const Locomotive* found = locomotive(loco);
    setFunction(loco, function, !(found && found->functionOn(function)));
}

void Railway::emergencyStop(std::uint32_t loco) {
    QPointer<Railway> self(this);
    locoCommand(loco, LocomotiveControl::EmergencyStop, -1, 0, commands::emergencyStop(cs2::LocId(loco)),
                QStringLiteral("%1: emergency stop").arg(locoName(loco)), [self, loco] {
                    // Document 2.4: the locomotive stands; the station does not announce its speed.
                    Locomotive* found = self ? self->state_.locomotives().find(loco) : nullptr;
                    if (found && found->confirmSpeed(0))
                        emit self->locomotivesChanged({loco});
                });
}

void Railway::configureDevice(std::uint32_t uid, std::uint8_t channel, std::uint16_t value) {
    const Device* found = device(uid);
    const DeviceSetting* setting = found ? found->setting(channel) : nullptr;
    if (!setting || !setting->accepts(value)) {
        emit problem(QStringLiteral("%1: setting %2 cannot take the value %3")
                         .arg(found ? found->name() : QString::number(uid, 16))
                         .arg(channel)
                         .arg(value));
        emit deviceConfigured(uid, channel, SettingResult::Refused);
        return;
    }
    const QString what = QStringLiteral("%1: %2 = %3").arg(found->name(), setting->title()).arg(value);
    QPointer<Railway> self(this);
    session_.request(commands::writeChannel(uid, channel, value),
                     [self, uid, channel, what](const station::CommandResult& result) {
                         if (!self)
                             return;
                         using Status = station::CommandResult::Status;
                         const SettingResult outcome = result.succeeded() ? SettingResult::Accepted
                                                       : result.status == Status::Rejected
                                                           ? SettingResult::Refused
                                                           : SettingResult::NoAnswer;
                         if (outcome != SettingResult::Accepted)
                             emit self->problem(commandProblem(what, result));
                         else
                             self->readSetting(uid, channel);
                         emit self->deviceConfigured(uid, channel, outcome);
                     });
}

// Asks the device for the value it now uses; the answer reaches the setting as a reading (0x0B, DLC 8).
void Railway::readSetting(std::uint32_t uid, std::uint8_t channel) {
    session_.request(commands::readChannel(uid, channel), [](const station::CommandResult&) {});
}

void Railway::stop() {
    powerCommand(false, commands::stop(), QStringLiteral("Stop (track power off)"));
}

void Railway::go() {
    powerCommand(true, commands::go(), QStringLiteral("Go (track power on)"));
}

} // namespace stellwerk::model
