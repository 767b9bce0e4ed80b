#include "station/StationSession.h"

#include "cs2/Codec.h"
#include "cs2/Request.h"

namespace stellwerk::station {

StationSession::StationSession(bus::Bus& bus, StationSettings settings, QObject* parent)
    : QObject(parent), bus_(bus), transport_(bus.transport()), settings_(settings), identity_(settings.uid),
      tracker_(new CommandTracker(
          [this](std::span<const can::CanFrame> f, CommandId id) { return sendFrames(f, id); },
          [this](CommandId id) { transport_.withdraw(id); }, this)),
      download_(new ConfigDownload(
          *tracker_, [this] { return identity_.hash(); }, this)),
      statusData_(new StatusDataReader(*tracker_, this)), liveness_(new Liveness([this] { ping(); }, this)) {
    download_->setRequestPolicy(settings_.commands);
    download_->setIdleTimeout(settings_.streamIdle);
    liveness_->setSettings(settings_.liveness);
    bus_.subscribe(busreading::Protocol::Cs2, this,
                   [this](const std::vector<can::CanFrame>& f) { receive(f); });
    connect(&transport_, &transport::Transport::stateChanged, this, &StationSession::transportStateChanged);
    connect(liveness_, &Liveness::stationSilent, this, &StationSession::stationSilent);
    connected_ = transport_.state() == transport::Transport::State::Connected;
    tracker_->setGiveUpObserver([this](auto firstSent) { commandGivenUp(firstSent); });
}

StationSession::~StationSession() {
    bus_.unsubscribe(this);
    disconnect(&transport_, nullptr, this, nullptr);
}

bool StationSession::send(const cs2::Message& message) {
    const can::CanFrame frame = cs2::encode(message);
    return sendFrames({&frame, 1});
}

bool StationSession::sendFrames(std::span<const can::CanFrame> frames, transport::SendTicket ticket) {
    if (frames.size() == 1)
        return transport_.send(identity_.stamp(frames.front()), ticket);
    std::vector<can::CanFrame> stamped;
    stamped.reserve(frames.size());
    for (const auto& frame : frames)
        stamped.push_back(identity_.stamp(frame));
    return transport_.sendBatch(stamped, ticket) == stamped.size();
}

void StationSession::transportStateChanged(transport::Transport::State state) {
    const bool connected = state == transport::Transport::State::Connected;
    if (connected_ && !connected) {
        connected_ = false;
        emit connectionLost();
        tracker_->cancelAll();
    }
    connected_ = connected;
}

// What we wrote may still sit in the connection (unsent, or being retransmitted to a station that is
// out of reach); a reset throws it away before the station is back.
void StationSession::stationSilent() {
    transport_.resetConnection(QStringLiteral("the station stopped answering; connection reset"));
}

// A command without an answer while the station said nothing at all since it was sent: the station may
// not have it yet, and must never get it now.
void StationSession::commandGivenUp(std::chrono::steady_clock::time_point firstSent) {
    if (lastHeard_ < firstSent)
        transport_.resetConnection(
            QStringLiteral("no answer to a command and nothing else from the station; connection reset"));
}

CommandId StationSession::request(const cs2::Message& command, CommandCallback done,
                                  std::optional<CommandPolicy> policy) {
    return tracker_->send(command, std::move(done), policy.value_or(settings_.commands));
}

void StationSession::ping() {
    send(cs2::request(cs2::Ping{}));
}

void StationSession::receive(const std::vector<can::CanFrame>& frames) {
    lastHeard_ = std::chrono::steady_clock::now();
    answerInBatch_ = false;
    for (const auto& frame : frames)
        receiveFrame(frame);
    download_->flushProgress();
    if (events_.hasUpdates()) {
        emit updated(events_.updates());
        events_.clear();
    }
    if (answerInBatch_)
        emit answersHeard();
}

void StationSession::receiveFrame(const can::CanFrame& frame) {
    ++counters_.frames;
    if (const auto newHash = identity_.observe(frame)) {
        ++counters_.hashCollisions;
        emit hashChanged(cs2::hash(frame), *newHash);
    }
    const auto decoded = cs2::decode(frame);
    if (!decoded) {
        ++counters_.undecodable;
        download_->feed(frame); // a broken 0x21 frame aborts the stream it belongs to
        return;
    }
    route(*decoded, frame);
}

void StationSession::route(const cs2::Message& message, const can::CanFrame& frame) {
    answerInBatch_ = answerInBatch_ || message.response;
    if (const auto* stream = std::get_if<cs2::ConfigDataStream>(&message.body)) {
        download_->feed(frame);
        if (stream->form == cs2::ConfigDataStream::Form::BroadcastHeader)
            events_.observe(message);
        return;
    }
    if (const auto* status = std::get_if<cs2::StatusDataConfig>(&message.body);
        status && status->form == cs2::StatusDataConfig::Form::Packet) {
        statusData_->feedPacket(*status, cs2::hash(frame));
        return;
    }
    if (const auto* ping = std::get_if<cs2::Ping>(&message.body);
        ping && ping->identity && message.response) {
        directory_.record(*ping->identity);
        liveness_->answered(*ping->identity);
    }
    if (message.response && tracker_->offer(message))
        ++counters_.answersMatched;
    events_.observe(message);
}

} // namespace stellwerk::station
