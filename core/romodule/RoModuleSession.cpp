#include "romodule/RoModuleSession.h"

#include "bus/Bus.h"
#include "transport/Transport.h"

#include <QRandomGenerator>

namespace stellwerk::romodule {
namespace {

using ro::Request;
using ro::Width;

// Inputs and change flags side by side (the simulator's 0x0020 and 0x0022) are polled with one read.
std::optional<Width> combinedWidth(const ro::RegisterBlock& inputs, const ro::RegisterBlock& flags) {
    const unsigned bytes = ro::byteCount(inputs.width);
    if (flags.address != inputs.address + bytes || flags.width != inputs.width)
        return std::nullopt;
    if (bytes == 1)
        return Width::Word;
    return bytes == 2 ? std::optional(Width::Long) : std::nullopt;
}

Request readOf(const ro::RegisterBlock& block, std::optional<Width> width = std::nullopt) {
    return Request{Request::Kind::Read, width.value_or(block.width), block.address, 0, 0};
}

std::uint32_t maskOf(int count) {
    return count >= 32 ? 0xFFFFFFFFu : (1u << count) - 1;
}

} // namespace

RoModuleSession::RoModuleSession(bus::Bus& bus, ro::RoProfile profile, SessionTiming timing, QObject* parent)
    : QObject(parent), bus_(bus), profile_(std::move(profile)), timing_(timing),
      nextJob_(timing.firstJob.value_or(std::uint8_t(QRandomGenerator::global()->bounded(256)))) {
    answerTimer_.setSingleShot(true);
    connect(&answerTimer_, &QTimer::timeout, this, &RoModuleSession::timedOut);
    connect(&pollTimer_, &QTimer::timeout, this, &RoModuleSession::poll);
    bus_.subscribe(busreading::Protocol::Ro, this,
                   [this](const std::vector<can::CanFrame>& frames) { receive(frames); });
}

RoModuleSession::~RoModuleSession() = default;

QString RoModuleSession::problem() const {
    if (const std::string problem = profile_.problem(); !problem.empty())
        return QString::fromStdString(profile_.name + ": " + problem);
    const auto& listed = bus_.profile().roModules();
    if (std::find(listed.begin(), listed.end(), profile_.ids) == listed.end())
        return QString::fromStdString(profile_.name + ": the bus profile does not list this module's ids");
    if (!profile_.ids.extended && !bus_.transport().carriesStandardFrames())
        return QString::fromStdString(profile_.name) +
               QStringLiteral(
                   ": 11-bit frames travel through a CAN adapter (QCanBus) only; %1 carries 29-bit "
                   "frames only")
                   .arg(bus_.transport().description());
    return {};
}

void RoModuleSession::start() {
    if (running_ || !problem().isEmpty())
        return;
    running_ = true;
    stopped_ = false;
    if (profile_.outputs.count)
        enqueue(Purpose::ReadOutputs, readOf(profile_.outputs));
    poll();
    pollTimer_.start(timing_.pollPeriod);
}

void RoModuleSession::stop() {
    running_ = false;
    stopped_ = true;
    pollTimer_.stop();
    answerTimer_.stop();
    queue_.clear();
    current_.reset();
    exchange_.reset();
}

bool RoModuleSession::setOutput(int number, bool on) {
    if (number < 1 || number > profile_.outputs.count)
        return false;
    const std::uint32_t bit = 1u << (number - 1);
    return changeOutputs(bit, on ? bit : 0);
}

bool RoModuleSession::switchAllOff() {
    return changeOutputs(outputMask(), 0);
}

RoModuleSession::RequestId RoModuleSession::read(std::uint16_t address, Width width) {
    enqueue(Purpose::User, Request{Request::Kind::Read, width, address, 0, 0}, ++lastRequestId_);
    return lastRequestId_;
}

RoModuleSession::RequestId RoModuleSession::write(std::uint16_t address, Width width, std::uint32_t value) {
    enqueue(Purpose::User, Request{Request::Kind::Write, width, address, 0, value}, ++lastRequestId_);
    return lastRequestId_;
}

bool RoModuleSession::changeOutputs(std::uint32_t mask, std::uint32_t values) {
    if (!running_ || state_ == State::Offline || profile_.outputs.count == 0)
        return false;
    pendingMask_ |= mask;
    pendingValues_ = (pendingValues_ & ~mask) | (values & mask);
    if (!queued(Purpose::WriteOutputs))
        enqueue(Purpose::WriteOutputs,
                Request{Request::Kind::Write, profile_.outputs.width, profile_.outputs.address});
    return true;
}

std::uint32_t RoModuleSession::outputMask() const {
    return maskOf(profile_.outputs.count);
}

void RoModuleSession::poll() {
    const ro::RegisterBlock& inputs = profile_.inputs;
    const auto& flags = profile_.changeFlags;
    if (inputs.count == 0 || queued(Purpose::Poll))
        return;
    const auto combined = flags ? combinedWidth(inputs, *flags) : std::nullopt;
    enqueue(Purpose::Poll, readOf(inputs, combined));
    if (flags && !combined)
        enqueue(Purpose::Poll, readOf(*flags));
}

void RoModuleSession::enqueue(Purpose purpose, Request request, RequestId id) {
    queue_.push_back(Job{purpose, request, id});
    sendNext();
}

bool RoModuleSession::queued(Purpose purpose) const {
    return std::any_of(queue_.begin(), queue_.end(),
                       [purpose](const Job& job) { return job.purpose == purpose; });
}

// One request in flight: the next one goes when the last one finished.
void RoModuleSession::sendNext() {
    if (current_ || queue_.empty() || stopped_)
        return;
    current_ = queue_.front();
    queue_.pop_front();
    Request request = current_->request;
    if (current_->purpose == Purpose::WriteOutputs) {
        if (pendingMask_ == 0) { // an earlier write took these changes along
            current_.reset();
            return sendNext();
        }
        if (!shadow_) { // the relays could not be read: a word written now would guess the others
            emit outputsFailed(pendingMask_, QStringLiteral("the relays have not been read yet"));
            pendingMask_ = 0;
            current_.reset();
            return sendNext();
        }
        writingMask_ = pendingMask_;
        writingValue_ = (*shadow_ & ~pendingMask_) | (pendingValues_ & pendingMask_);
        pendingMask_ = 0;
        request.value = writingValue_;
    }
    request.job = takeJob();
    exchange_.emplace(
        request, [this] { return takeJob(); }, timing_.limits);
    transmit();
}

void RoModuleSession::transmit() {
    exchange_->sent();
    bus_.transport().send(profile_.requestFrame(exchange_->request()));
    answerTimer_.start(timing_.answerTimeout);
}

void RoModuleSession::receive(const std::vector<can::CanFrame>& frames) {
    for (const can::CanFrame& frame : frames) {
        if (ro::directionOf(frame, profile_.ids) != ro::Direction::Answer)
            continue; // another module's frames, or a request (ours, or another master's)
        const auto answer = ro::decodeAnswer(frame.payload());
        if (!answer)
            ++counters_.malformed;
        else if (!exchange_)
            ++counters_.unsolicited;
        else
            answered(*answer);
    }
}

void RoModuleSession::answered(const ro::Answer& answer) {
    const bool ours = std::visit(
        [this](const auto& a) {
            using A = std::decay_t<decltype(a)>;
            if constexpr (std::is_same_v<A, ro::InvalidCommandAnswer>)
                return true;
            else
                return a.job == exchange_->request().job;
        },
        answer);
    if (!ours) {
        ++counters_.stale;
        return;
    }
    counters_.duplicates += std::holds_alternative<ro::DuplicateJobAnswer>(answer);
    counters_.invalid += std::holds_alternative<ro::InvalidCommandAnswer>(answer);
    if (state_ != State::Online)
        setState(State::Online); // it answers: whatever it says, it is there
    follow(exchange_->answered(answer));
}

void RoModuleSession::timedOut() {
    if (!exchange_)
        return;
    ++counters_.timeouts;
    follow(exchange_->timedOut());
}

void RoModuleSession::follow(const ro::Step& step) {
    if (step.kind == ro::Step::Kind::Send)
        transmit();
    else if (step.kind == ro::Step::Kind::Finish)
        finish(*step.outcome);
}

void RoModuleSession::finish(const ro::Outcome& outcome) {
    answerTimer_.stop();
    counters_.ok += outcome.succeeded();
    counters_.flagsLost += outcome.reissued;
    const Job job = *current_;
    if (job.purpose == Purpose::WriteOutputs)
        finishOutputs(outcome);
    else if (job.purpose == Purpose::ReadOutputs && outcome.succeeded())
        readOutputs(outcome.value);
    else if (job.purpose == Purpose::Poll && outcome.succeeded())
        finishPoll(outcome.value);
    else if (job.purpose == Purpose::User)
        emit requestFinished(job.id, outcome);
    current_.reset();
    exchange_.reset();
    if (outcome.kind == ro::Outcome::Kind::NoAnswer)
        goOffline();
    sendNext();
}

void RoModuleSession::readOutputs(std::uint32_t value) {
    shadow_ = value & outputMask();
    emit outputsChanged(*shadow_);
}

void RoModuleSession::finishOutputs(const ro::Outcome& outcome) {
    if (outcome.succeeded()) {
        shadow_ = writingValue_;
        emit outputsChanged(*shadow_);
    } else {
        emit outputsFailed(writingMask_, QString::fromStdString(outcome.text()));
    }
    writingMask_ = 0;
    if (pendingMask_ && outcome.kind != ro::Outcome::Kind::NoAnswer && !queued(Purpose::WriteOutputs))
        queue_.push_back(Job{Purpose::WriteOutputs, current_->request});
}

void RoModuleSession::finishPoll(std::uint32_t value) {
    const ro::RegisterBlock& inputs = profile_.inputs;
    const bool flagsOnly = profile_.changeFlags &&
                           current_->request.address == profile_.changeFlags->address &&
                           current_->request.address != inputs.address;
    const unsigned shift = 8 * ro::byteCount(inputs.width);
    const std::uint32_t mask = maskOf(inputs.count);
    const bool combined = current_->request.width != inputs.width;
    const std::uint32_t changed = flagsOnly ? value & mask : combined ? (value >> shift) & mask : 0;
    const std::uint32_t now = flagsOnly ? inputs_.value_or(0) : value & mask;
    if (inputs_ != now || changed) {
        inputs_ = now;
        emit inputsChanged(now, changed);
    }
}

// It stopped answering: what waits is given up (a switch later than asked is worse than none), the
// shadow is read again when it is back, since its relays may have changed meanwhile (power, another master).
void RoModuleSession::goOffline() {
    setState(State::Offline);
    if (pendingMask_)
        emit outputsFailed(pendingMask_, QStringLiteral("module offline"));
    pendingMask_ = 0;
    for (const Job& job : queue_)
        if (job.purpose == Purpose::User)
            emit requestFinished(job.id, ro::Outcome{ro::Outcome::Kind::NoAnswer});
    queue_.clear();
    shadow_.reset();
}

void RoModuleSession::setState(State state) {
    if (state_ == state)
        return;
    const State before = state_;
    state_ = state;
    if (before == State::Offline && state == State::Online && profile_.outputs.count &&
        !queued(Purpose::ReadOutputs))
        queue_.push_front(Job{Purpose::ReadOutputs, readOf(profile_.outputs)});
    emit stateChanged(state);
}

} // namespace stellwerk::romodule
