#include "monitor/BusMonitorReplay.h"

#include <QFile>
#include <QTimer>
#include <algorithm>
#include <cmath>

namespace stellwerk::ui {

BusMonitorReplay::BusMonitorReplay(QObject* parent) : QObject(parent), m_timer(new QTimer(this)) {
    m_timer->setSingleShot(true);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &BusMonitorReplay::playDue);
}

BusMonitorReplay::~BusMonitorReplay() = default;

QString BusMonitorReplay::start(const QString& path) {
    QFile probe(path); // a file that cannot be read leaves a running replay alone
    if (!probe.open(QIODevice::ReadOnly))
        return probe.errorString();
    probe.close();
    stop();
    const QString error = m_reader.open(path);
    if (!error.isEmpty())
        return error;
    m_pending.reset();
    m_pendingEnd = 0;
    m_playedEnd = 0;
    m_haveLogTime = false;
    m_lastLogUs = 0;
    m_anchorLogUs = 0;
    m_played = 0;
    m_skipped = 0;
    m_percent = 0;
    setState(State::Playing);
    emit progressChanged(0);
    m_clock.start();
    m_timer->start(0);
    return {};
}

void BusMonitorReplay::setSpeed(double factor) {
    factor = std::max(factor, 0.0);
    if (factor == m_speed)
        return;
    rebase();
    m_speed = factor;
    if (m_state == State::Playing)
        scheduleNext();
}

void BusMonitorReplay::pause() {
    if (m_state != State::Playing)
        return;
    rebase();
    m_timer->stop();
    setState(State::Paused);
}

void BusMonitorReplay::resume() {
    if (m_state != State::Paused)
        return;
    m_clock.start();
    setState(State::Playing);
    scheduleNext();
}

void BusMonitorReplay::stop() {
    m_timer->stop();
    m_pending.reset();
    setState(State::Idle);
}

int BusMonitorReplay::percent() const {
    return m_percent;
}

void BusMonitorReplay::setState(State state) {
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged(state);
}

// The log time that is due now: where the clock was anchored plus the time since, scaled.
qint64 BusMonitorReplay::logNowUs() const {
    if (m_speed == AsFastAsPossible || m_state != State::Playing)
        return m_anchorLogUs;
    return m_anchorLogUs + qint64(double(m_clock.nsecsElapsed() / 1000) * m_speed);
}

// Makes the present the new anchor, before the speed changes or the clock stops.
void BusMonitorReplay::rebase() {
    m_anchorLogUs = logNowUs();
    m_clock.start();
}

// Reads lines until the next frame (reporting the ones without); false at the end of the file.
bool BusMonitorReplay::readPending() {
    while (!m_pending) {
        std::optional<BusMonitorLogLine> line = m_reader.next();
        if (!line)
            return false;
        if (!line->frame) {
            ++m_skipped;
            emit lineSkipped(line->number, line->problem);
            continue;
        }
        if (line->timeUs && !m_haveLogTime) { // the first stamp starts the clock
            m_haveLogTime = true;
            m_anchorLogUs = *line->timeUs;
            m_clock.start();
        }
        m_pending = std::move(line);
        m_pendingEnd = m_reader.position();
    }
    return true;
}

// Delivers every frame that is due (frames with one time stamp as one batch), at most LinesPerTurn.
void BusMonitorReplay::playDue() {
    int budget = LinesPerTurn;
    while (m_state == State::Playing && budget-- > 0 && readPending()) {
        const qint64 due = m_pending->timeUs.value_or(m_lastLogUs);
        if (m_speed != AsFastAsPossible && due > logNowUs())
            break;
        if (m_speed == AsFastAsPossible)
            m_anchorLogUs = std::max(m_anchorLogUs, due);
        const QDateTime time =
            m_haveLogTime ? QDateTime::fromMSecsSinceEpoch((due + 500) / 1000) : QDateTime::currentDateTime();
        std::vector<can::CanFrame> batch{*m_pending->frame};
        const bool outgoing = m_pending->sent;
        const int bus = m_pending->bus;
        m_lastLogUs = due;
        m_playedEnd = m_pendingEnd;
        m_pending.reset();
        while (budget-- > 0 && readPending() && m_pending->timeUs.value_or(m_lastLogUs) == due &&
               m_pending->sent == outgoing && m_pending->bus == bus) {
            batch.push_back(*m_pending->frame);
            m_playedEnd = m_pendingEnd;
            m_pending.reset();
        }
        m_played += qsizetype(batch.size());
        emit framesReplayed(batch, time, outgoing, bus);
    }
    if (m_state == State::Playing && !m_pending && !readPending()) {
        m_playedEnd = m_reader.size();
        reportProgress();
        return setState(State::Finished);
    }
    reportProgress();
    if (m_state == State::Playing)
        scheduleNext();
}

// The share of the file up to the end of the last line played.
void BusMonitorReplay::reportProgress() {
    const int now = m_reader.size() > 0 ? int(m_playedEnd * 100 / m_reader.size()) : 100;
    if (now == m_percent)
        return;
    m_percent = now;
    emit progressChanged(now);
}

void BusMonitorReplay::scheduleNext() {
    if (!m_pending || m_speed == AsFastAsPossible)
        return m_timer->start(0);
    const qint64 waitUs = m_pending->timeUs.value_or(m_lastLogUs) - logNowUs();
    const double waitMs = std::ceil(double(std::max<qint64>(waitUs, 0)) / 1000.0 / m_speed);
    m_timer->start(int(std::min(waitMs, 3600000.0)));
}

} // namespace stellwerk::ui
