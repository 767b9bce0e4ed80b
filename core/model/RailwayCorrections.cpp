// The Railway after trouble: the book of commands the station did not confirm, what is brought back when
// the station is heard again, and "bring the layout back in step".

#include "model/Railway.h"
#include "station/StateQueries.h"
#include "station/StationSession.h"

#include <QPointer>
#include <QTimer>

namespace stellwerk::model {
namespace {

using Kind = CommandTarget::Kind;

UnconfirmedCommands::Clock::time_point now() {
    return UnconfirmedCommands::Clock::now();
}

// Whether a target belongs to what one batch changed.
bool touched(const CommandTarget& target, const RailwayChanges& changes) {
    switch (target.kind) {
    case Kind::Speed:
    case Kind::Direction:
    case Kind::Function:
        return changes.locomotives.contains(std::uint32_t(target.id));
    case Kind::Accessory:
        return changes.accessories.contains(target.id);
    case Kind::Address:
        return changes.addresses.contains(target.id);
    case Kind::Power:
        return changes.power.has_value();
    }
    return false;
}

} // namespace

// What the station reported for a target since the state was last lost; nullopt when it did not.
std::optional<int> Railway::reportedValue(CommandTarget target) const {
    const Locomotive* loco = target.isLocomotive() ? locomotive(std::uint32_t(target.id)) : nullptr;
    switch (target.kind) {
    case Kind::Speed:
        return loco && loco->isSpeedReported() ? std::optional<int>(loco->speed()) : std::nullopt;
    case Kind::Direction:
        return loco && loco->isDirectionReported()
                   ? std::optional<int>(loco->direction() == cs2::Direction::Backward ? 1 : 0)
                   : std::nullopt;
    case Kind::Function:
        return loco && loco->isFunctionReported(target.functionNumber)
                   ? std::optional<int>(loco->functionOn(target.functionNumber) ? 1 : 0)
                   : std::nullopt;
    case Kind::Accessory: {
        const Accessory* found = accessory(target.id);
        return found && found->isPositionReported() && found->position() >= 0
                   ? std::optional<int>(found->position())
                   : std::nullopt;
    }
    case Kind::Address:
        return addressPosition(target.id);
    case Kind::Power:
        return power() ? std::optional<int>(*power() != station::PowerState::Stopped ? 1 : 0) : std::nullopt;
    }
    return std::nullopt;
}

// A command that may have reached the station without its answer reaching us goes into the book; an
// acknowledged one tells the book what is confirmed now. A refused or unsent one changed nothing.
void Railway::recordOutcome(CommandTarget target, int value, std::optional<int> confirmedAtSend,
                            const station::CommandResult& result) {
    using Status = station::CommandResult::Status;
    if (result.succeeded()) {
        unconfirmed_.acknowledged(target, value, now());
    } else if (result.status == Status::TimedOut || result.status == Status::Cancelled) {
        const std::optional<int> confirmed = reportedValue(target);
        unconfirmed_.failed(target, value, confirmed ? confirmed : confirmedAtSend);
    }
}

void Railway::checkReports(const RailwayChanges& changes) {
    if (unconfirmed_.empty())
        return;
    unconfirmed_.settle(now());
    for (const CommandTarget target : unconfirmed_.targets())
        if (touched(target, changes))
            checkReport(target);
}

void Railway::checkReport(CommandTarget target) {
    const std::optional<int> value = reportedValue(target);
    if (!value)
        return;
    if (const std::optional<Correction> correction = unconfirmed_.reported(target, *value, now()))
        correct(*correction);
}

// The station answers again: whatever it may still carry out of a failed command is undone now, or, for
// a locomotive, once the station said what it has.
void Railway::answersHeard() {
    if (unconfirmed_.empty())
        return;
    unconfirmed_.settle(now());
    const Recovery recovery = unconfirmed_.heardAgain(now());
    for (const Correction& correction : recovery.corrections)
        correct(correction);
    for (const CommandTarget target : recovery.queries)
        askFor(target);
}

// The answer reaches the state as a report like any other; it is checked once the batch that carried it
// has been applied, also when the value did not change.
void Railway::askFor(CommandTarget target) {
    const cs2::LocId loco(std::uint32_t(target.id));
    const cs2::Message query = target.kind == Kind::Speed ? station::speedQuery(loco)
                               : target.kind == Kind::Direction
                                   ? station::directionQuery(loco)
                                   : station::functionQuery(loco, std::uint8_t(target.functionNumber));
    QPointer<Railway> self(this);
    session_.request(query, [self, target](const station::CommandResult& result) {
        if (!self)
            return;
        if (!result.succeeded())
            return self->unconfirmed_.queryUnanswered(target);
        QTimer::singleShot(0, self, [self, target] {
            if (self)
                self->checkReport(target);
        });
    });
}

void Railway::correct(const Correction& correction) {
    emit stateCorrected(correction);
    if (!correction.sentValue)
        return;
    const int value = *correction.sentValue;
    const auto id = correction.target.id;
    switch (correction.target.kind) {
    case Kind::Speed:
        return setSpeed(std::uint32_t(id), value);
    case Kind::Direction:
        return setDirection(std::uint32_t(id), value ? cs2::Direction::Backward : cs2::Direction::Forward);
    case Kind::Function:
        return setFunction(std::uint32_t(id), correction.target.functionNumber, value != 0);
    case Kind::Accessory:
        return switchAccessory(id, value);
    case Kind::Address:
        return switchAddress(id, value);
    case Kind::Power:
        return value ? go() : stop();
    }
}

void Railway::bringBackInStep() {
    answersHeard();
    for (const Locomotive& loco : state_.locomotives().items()) {
        const CommandTarget speed = CommandTarget::speed(loco.id().value());
        const std::optional<int> confirmed =
            unconfirmed_.restoreValue(speed) ? unconfirmed_.restoreValue(speed) : reportedValue(speed);
        setSpeed(loco.id().value(), aftermath() == Aftermath::StopLocomotives ? 0 : confirmed.value_or(0));
    }
    delete resync_;
    resync_ = new station::StateQueryRound(session_, stateQueries(), 8, this);
    connect(resync_, &station::StateQueryRound::problem, this, &Railway::problem);
    connect(resync_, &station::StateQueryRound::finished, this, [this] {
        const auto answered = int(resync_->answered());
        const auto unanswered = int(resync_->failed());
        resync_->deleteLater();
        resync_ = nullptr;
        emit backInStep(answered, unanswered);
    });
    resync_->start();
}

// Every state the station can report: each locomotive's speed, direction and functions, each contact.
std::vector<cs2::Message> Railway::stateQueries() const {
    std::vector<cs2::Message> queries;
    for (const Locomotive& loco : state_.locomotives().items()) {
        std::vector<int> functions;
        for (const LocomotiveFunction& function : loco.functions())
            functions.push_back(function.number);
        for (cs2::Message& query : station::locomotiveQueries(loco.id(), functions))
            queries.push_back(std::move(query));
    }
    for (const FeedbackContact& contact : state_.contacts().items())
        queries.push_back(station::contactQuery(contact.device(), contact.contact()));
    return queries;
}

} // namespace stellwerk::model
