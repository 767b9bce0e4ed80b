#include "station/StateQueries.h"

#include "cs2/Request.h"
#include "station/StationSession.h"

#include <QPointer>

namespace stellwerk::station {

cs2::Message speedQuery(cs2::LocId loco) {
    return cs2::request(cs2::LocoSpeed{loco, std::nullopt});
}

cs2::Message directionQuery(cs2::LocId loco) {
    return cs2::request(cs2::LocoDirection{loco, std::nullopt});
}

cs2::Message functionQuery(cs2::LocId loco, std::uint8_t function) {
    cs2::LocoFunction query;
    query.loco = loco;
    query.function = function;
    return cs2::request(query);
}

std::vector<cs2::Message> locomotiveQueries(cs2::LocId loco, const std::vector<int>& functions) {
    std::vector<cs2::Message> queries{speedQuery(loco), directionQuery(loco)};
    for (const int number : functions)
        if (number >= 0 && number < 32)
            queries.push_back(functionQuery(loco, std::uint8_t(number)));
    return queries;
}

cs2::Message contactQuery(std::int64_t device, std::int64_t contact) {
    cs2::S88Event query;
    query.device = std::uint16_t(device);
    query.contact = std::uint16_t(contact);
    return cs2::request(query);
}

StateQueryRound::StateQueryRound(StationSession& session, std::vector<cs2::Message> queries, int inFlight,
                                 QObject* parent)
    : QObject(parent), session_(session), queries_(queries.begin(), queries.end()),
      maxInFlight_(std::max(inFlight, 1)), count_(queries.size()) {}

void StateQueryRound::start() {
    started_ = true;
    pump();
}

void StateQueryRound::abandon() {
    abandoned_ = true;
    queries_.clear();
}

void StateQueryRound::pump() {
    while (inFlight_ < maxInFlight_ && !queries_.empty()) {
        const cs2::Message query = queries_.front();
        queries_.pop_front();
        ++inFlight_;
        QPointer<StateQueryRound> self(this);
        session_.request(query, [self, query](const CommandResult& r) {
            if (!self)
                return;
            --self->inFlight_;
            if (self->abandoned_)
                return;
            if (r.succeeded()) {
                ++self->answered_;
            } else {
                ++self->failed_;
                const std::string_view name = cs2::messageName(query.body);
                emit self->problem(
                    QStringLiteral("%1: %2").arg(QLatin1String(name.data(), qsizetype(name.size())),
                                                 QLatin1String(commandStatusName(r.status))));
            }
            self->pump();
        });
    }
    if (started_ && !abandoned_ && inFlight_ == 0 && queries_.empty()) {
        started_ = false; // once
        emit finished();
    }
}

} // namespace stellwerk::station
