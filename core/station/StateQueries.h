#pragma once

#include "cs2/LocId.h"
#include "cs2/Messages.h"
#include "station/CommandTracker.h"

#include <QObject>
#include <QString>
#include <cstdint>
#include <deque>
#include <vector>

namespace stellwerk::station {

class StationSession;

// The questions that read a locomotive's state (speed, direction, each of its functions) and a feedback
// contact's (document 3.4-3.6, 3.17): what the start-up and "bring the layout back in step" ask.
std::vector<cs2::Message> locomotiveQueries(cs2::LocId loco, const std::vector<int>& functions);
cs2::Message speedQuery(cs2::LocId loco);
cs2::Message directionQuery(cs2::LocId loco);
cs2::Message functionQuery(cs2::LocId loco, std::uint8_t function);
cs2::Message contactQuery(std::int64_t device, std::int64_t contact);

// Asks a list of state questions with a few in flight at a time (the answers reach the railway as
// station updates, like any report), counts answers and failures and says once when all have ended.
class StateQueryRound final : public QObject {
    Q_OBJECT

public:
    StateQueryRound(StationSession& session, std::vector<cs2::Message> queries, int inFlight = 8,
                    QObject* parent = nullptr);

    void start();
    // Stops sending; finished() is not emitted.
    void abandon();

    std::size_t queryCount() const { return count_; }
    std::size_t answered() const { return answered_; }
    std::size_t failed() const { return failed_; }

signals:
    // A question got no answer: its name and why ("loco.speed: no acknowledgement").
    void problem(const QString& message);
    void finished();

private:
    void pump();

    StationSession& session_;
    std::deque<cs2::Message> queries_;
    int maxInFlight_;
    int inFlight_ = 0;
    std::size_t count_ = 0;
    std::size_t answered_ = 0;
    std::size_t failed_ = 0;
    bool abandoned_ = false;
    bool started_ = false;
};

} // namespace stellwerk::station
