#include "model/ReadingPoller.h"

#include "model/Commands.h"
#include "station/StationSession.h"

#include <QPointer>
#include <QTimer>
#include <algorithm>

namespace stellwerk::model {
namespace {

constexpr std::chrono::milliseconds DefaultInterval{1000};
constexpr std::chrono::milliseconds LongestWait{500};

} // namespace

ReadingPoller::ReadingPoller(station::StationSession& session, QObject* parent)
    : QObject(parent), session_(session), timer_(new QTimer(this)) {
    timer_->setInterval(DefaultInterval);
    connect(timer_, &QTimer::timeout, this, &ReadingPoller::poll);
}

ReadingPoller::~ReadingPoller() {
    for (const station::CommandId id : sent_)
        session_.tracker().forget(id);
}

void ReadingPoller::setSources(std::vector<ReadingSource> sources) {
    sources_ = std::move(sources);
}

void ReadingPoller::setInterval(std::chrono::milliseconds interval) {
    timer_->setInterval(interval);
}

std::chrono::milliseconds ReadingPoller::interval() const {
    return timer_->intervalAsDuration();
}

void ReadingPoller::start() {
    started_ = true;
    if (!active_)
        return;
    poll();
    timer_->start();
}

void ReadingPoller::stop() {
    started_ = false;
    timer_->stop();
}

void ReadingPoller::setActive(bool active) {
    if (active == active_)
        return;
    active_ = active;
    if (!active_)
        timer_->stop();
    else if (started_)
        start();
}

bool ReadingPoller::running() const {
    return timer_->isActive();
}

void ReadingPoller::poll() {
    for (const ReadingSource& source : sources_)
        if (!pending_.contains(source))
            request(source);
}

void ReadingPoller::request(ReadingSource source) {
    // Answer within most of an interval, so that the next tick finds the channel free again.
    station::CommandPolicy policy{std::min(LongestWait, interval() * 4 / 5), 0};
    const cs2::Message read = commands::readChannel(source.device, source.channel);
    pending_.insert(source);
    QPointer<ReadingPoller> self(this);
    auto id = std::make_shared<station::CommandId>(0);
    *id = session_.request(
        read,
        [self, source, id](const station::CommandResult& result) {
            if (!self)
                return;
            self->pending_.erase(source);
            std::erase(self->sent_, *id);
            if (!result.succeeded())
                emit self->readingMissed(source.device, source.channel);
        },
        policy);
    if (*id != 0)
        sent_.push_back(*id);
}

} // namespace stellwerk::model
