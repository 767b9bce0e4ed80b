#include "model/Programmer.h"

#include "model/Commands.h"
#include "station/StationSession.h"

#include <QPointer>
#include <QTimer>

namespace stellwerk::model {

namespace {

using Task = ProgrammingResult::Task;
using Outcome = ProgrammingResult::Outcome;
using Problem = ProgrammingResult::Problem;

constexpr int MaxCv = Programmer::MaxCv;
constexpr int MaxMm2Cv = Programmer::MaxMm2Cv;
constexpr int Sx1Cvs = 5;
constexpr int MaxIndex = Programmer::MaxIndex;
constexpr int MainTrackRange = 64;

ProgrammingResult invalid(Task task, const CvTarget& target, Problem problem, int minimum = 0,
                          int maximum = 0) {
    ProgrammingResult result;
    result.task = task;
    result.outcome = Outcome::Invalid;
    result.problem = problem;
    result.target = target;
    result.minimum = minimum;
    result.maximum = maximum;
    return result;
}

// The CV and index rules both directions share (document 3.7/3.8, "Protokolltypische Wertebereiche").
std::optional<ProgrammingResult> checkTarget(Task task, const CvTarget& target, int lastCv, int firstIndex) {
    if (target.cv < 1 || target.cv > lastCv)
        return invalid(task, target, Problem::CvOutOfRange, 1, lastCv);
    const bool mfx = target.decoder.protocol() == cs2::Protocol::Mfx;
    if (!mfx && target.index != 0)
        return invalid(task, target, Problem::IndexNotMfx);
    if (mfx && (target.index < firstIndex || target.index > MaxIndex))
        return invalid(task, target, Problem::IndexOutOfRange, firstIndex, MaxIndex);
    return std::nullopt;
}

} // namespace

std::uint8_t CvWrite::bitValue(int position, bool on) {
    return std::uint8_t(0xF0 | (on ? 0x08 : 0x00) | (position & 0x07));
}

Programmer::Programmer(station::StationSession& session, QObject* parent)
    : Programmer(session, Settings{}, parent) {}

Programmer::Programmer(station::StationSession& session, Settings settings, QObject* parent)
    : QObject(parent), session_(session), settings_(settings), discoveryTimer_(new QTimer(this)) {
    qRegisterMetaType<ProgrammingResult>();
    discoveryTimer_->setSingleShot(true);
    connect(discoveryTimer_, &QTimer::timeout, this, &Programmer::discoveryTimedOut);
    connect(&session_, &station::StationSession::updated, this, &Programmer::observe);
}

Programmer::~Programmer() = default;

std::optional<ProgrammingResult> Programmer::checkRead(const CvTarget& target) {
    switch (target.decoder.protocol()) {
    case cs2::Protocol::Mm2:
        return invalid(Task::ReadCv, target, Problem::Mm2CannotBeRead);
    case cs2::Protocol::Dcc:
    case cs2::Protocol::Mfx:
        return checkTarget(Task::ReadCv, target, MaxCv, 0);
    case cs2::Protocol::Sx1:
        return checkTarget(Task::ReadCv, target, Sx1Cvs, 0);
    default:
        return invalid(Task::ReadCv, target, Problem::NotProgrammable);
    }
}

std::optional<ProgrammingResult> Programmer::checkWrite(const CvWrite& write) {
    const cs2::Protocol protocol = write.target.decoder.protocol();
    const bool dcc = protocol == cs2::Protocol::Dcc;
    std::optional<ProgrammingResult> problem;
    switch (protocol) {
    case cs2::Protocol::Dcc:
        problem = checkTarget(Task::WriteCv, write.target, MaxCv, 0);
        break;
    case cs2::Protocol::Mfx: // 3.8: the write index is 1..63
        problem = checkTarget(Task::WriteCv, write.target, MaxCv, 1);
        break;
    case cs2::Protocol::Mm2:
        problem = checkTarget(Task::WriteCv, write.target, MaxMm2Cv, 0);
        break;
    case cs2::Protocol::Sx1:
        problem = checkTarget(Task::WriteCv, write.target, Sx1Cvs, 0);
        if (!problem && write.track == ProgrammingTrack::Main)
            problem = invalid(Task::WriteCv, write.target, Problem::ProgrammingTrackOnly);
        break;
    default:
        return invalid(Task::WriteCv, write.target, Problem::NotProgrammable);
    }
    if (problem)
        return problem;
    if (!dcc && write.mode != cs2::DccProgrammingMode::Direct)
        return invalid(Task::WriteCv, write.target, Problem::ModeNotDcc);
    if (write.mode == cs2::DccProgrammingMode::Reserved)
        return invalid(Task::WriteCv, write.target, Problem::ReservedMode);
    if (write.mode == cs2::DccProgrammingMode::Bit && (write.value & 0xF0) != 0xF0)
        return invalid(Task::WriteCv, write.target, Problem::BitValueForm);
    return std::nullopt;
}

bool Programmer::start(Task task) {
    if (!task_) {
        task_ = task;
        return true;
    }
    ProgrammingResult result;
    result.task = task;
    result.outcome = Outcome::Busy;
    emit finished(result);
    return false;
}

bool Programmer::refuse(ProgrammingResult result) {
    emit finished(result);
    return false;
}

bool Programmer::discover() {
    if (!start(Task::Discovery))
        return false;
    // Form 2 with protocol 32: the station runs a whole mfx search and reports its steps (3.1).
    if (!session_.send(commands::discoverMfx(std::uint8_t(DiscoverySteps)))) {
        ProgrammingResult result;
        result.task = Task::Discovery;
        result.outcome = Outcome::NotSent;
        finish(result);
        return false;
    }
    discoveryTimer_->start(settings_.discoveryTimeout);
    return true;
}

bool Programmer::bind(std::uint32_t mfxUid, std::uint16_t sid) {
    return registration(Task::Bind, mfxUid, sid, commands::bindMfx(mfxUid, sid));
}

bool Programmer::verify(std::uint32_t mfxUid, std::uint16_t sid) {
    return registration(Task::Verify, mfxUid, sid, commands::verifyMfx(mfxUid, sid));
}

// Bind and verify name a decoder and the SID it gets or should have; SID 0 is no SID.
bool Programmer::registration(Task task, std::uint32_t mfxUid, std::uint16_t sid,
                              const cs2::Message& message) {
    ProgrammingResult result;
    result.task = task;
    result.mfxUid = mfxUid;
    result.sid = sid;
    if (sid == 0) {
        result.outcome = Outcome::Invalid;
        result.problem = Problem::NoSid;
        return refuse(result);
    }
    if (!start(task))
        return false;
    request(message, result);
    return true;
}

bool Programmer::readCv(const CvTarget& target) {
    if (const auto problem = checkRead(target))
        return refuse(*problem);
    if (!start(Task::ReadCv))
        return false;
    ProgrammingResult result;
    result.task = Task::ReadCv;
    result.target = target;
    request(commands::readCv(target.decoder, {target.cv, target.index}), result);
    return true;
}

bool Programmer::writeCv(const CvWrite& write) {
    if (const auto problem = checkWrite(write))
        return refuse(*problem);
    if (!start(Task::WriteCv))
        return false;
    ProgrammingResult result;
    result.task = Task::WriteCv;
    result.target = write.target;
    result.value = write.value;
    const cs2::CvAddress cv{write.target.cv, write.target.index};
    request(commands::writeCv(write.target.decoder, cv, write.value, write.track == ProgrammingTrack::Main,
                              write.mode),
            result);
    return true;
}

// One command, one answer; no retry: the station does not queue programming commands (3.1-3.8).
void Programmer::request(const cs2::Message& message, ProgrammingResult result) {
    const station::CommandPolicy policy{settings_.answerTimeout, 0};
    QPointer<Programmer> self(this);
    session_.request(
        message,
        [self, result](const station::CommandResult& command) {
            if (self)
                self->answered(result, command);
        },
        policy);
}

void Programmer::answered(ProgrammingResult result, const station::CommandResult& command) {
    using Status = station::CommandResult::Status;
    switch (command.status) {
    case Status::Acknowledged:
        result.outcome = Outcome::Done;
        break;
    case Status::Rejected:
        result.outcome = Outcome::Refused;
        break;
    case Status::TimedOut:
        result.outcome = Outcome::NoAnswer;
        break;
    case Status::NotSent:
    case Status::Cancelled:
        result.outcome = Outcome::NotSent;
        break;
    }
    if (command.answer) {
        if (const auto* read = std::get_if<cs2::ConfigRead>(&command.answer->body))
            result.value = read->value;
        if (const auto* written = std::get_if<cs2::ConfigWrite>(&command.answer->body))
            result.verified = (written->flags & cs2::ConfigWrite::VerifyOk) != 0;
        if (const auto* verified = std::get_if<cs2::MfxVerify>(&command.answer->body))
            result.ask = verified->ask;
    }
    finish(result);
}

void Programmer::observe(const station::StationUpdates& updates) {
    for (const cs2::LocoDiscovery& answer : updates.discoveries)
        if (task_ == Task::Discovery)
            discoveryAnswer(answer);
}

void Programmer::discoveryAnswer(const cs2::LocoDiscovery& answer) {
    ProgrammingResult result;
    result.task = Task::Discovery;
    if (!answer.uid) { // 3.1: negative answer, DLC 0
        result.outcome = Outcome::NotFound;
        finish(result);
        return;
    }
    // Main-track requests count from 64 ("Range = Wert mod 64"); 33..39 answer MM2/DCC/SX1 recognition.
    const int range = answer.range.value_or(0) % MainTrackRange;
    if (range < 1 || range > DiscoverySteps)
        return;
    discoveryTimer_->start(settings_.discoveryTimeout);
    emit discoveryProgress(range, *answer.uid);
    if (range < DiscoverySteps)
        return;
    result.mfxUid = *answer.uid;
    result.ask = answer.ask;
    finish(result);
}

void Programmer::discoveryTimedOut() {
    if (task_ != Task::Discovery)
        return;
    ProgrammingResult result;
    result.task = Task::Discovery;
    result.outcome = Outcome::NoAnswer;
    finish(result);
}

void Programmer::finish(const ProgrammingResult& result) {
    if (result.task == Task::Discovery)
        discoveryTimer_->stop();
    task_.reset();
    emit finished(result);
}

} // namespace stellwerk::model
