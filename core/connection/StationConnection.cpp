#include "connection/StationConnection.h"

#include "cs2config/ConfigStreamKeys.h"
#include "transport/TransportAddress.h"
#include "transport/TransportFactory.h"

namespace stellwerk::connection {

// Everything one connection owns, torn down together: the start-up and the session before the
// transport they use, the transport before the local station it talks to.
class StationLink final : public QObject {
public:
    ~StationLink() override {
        startup.reset();
        session.reset();
        transport.reset();
        local.reset();
    }

    // Stops every signal from the link's parts to `receiver`.
    void detach(const QObject* receiver) {
        for (const QObject* part :
             {static_cast<const QObject*>(transport.get()), static_cast<const QObject*>(startup.get()),
              session ? static_cast<const QObject*>(&session->liveness()) : nullptr})
            if (part)
                QObject::disconnect(part, nullptr, receiver, nullptr);
    }

    std::unique_ptr<transport::LocalPeer> local;
    std::unique_ptr<transport::Transport> transport;
    std::unique_ptr<station::StationSession> session;
    std::unique_ptr<station::StartupSequence> startup;
};

namespace {

LoadingStep loadingStep(station::StartupSequence::Step step) {
    using Step = station::StartupSequence::Step;
    switch (step) {
    case Step::Devices:
        return LoadingStep::ListingDevices;
    case Step::WakeUp:
        return LoadingStep::WakingUp;
    case Step::StatusData:
        return LoadingStep::ReadingDevices;
    case Step::Configuration:
        return LoadingStep::DownloadingFiles;
    case Step::States:
    case Step::Ready:
        break;
    }
    return LoadingStep::ReadingStates;
}

} // namespace

std::optional<int> LoadingProgress::percent() const {
    if (announced <= 0)
        return std::nullopt;
    return int(std::min<qsizetype>(100, received * 100 / announced));
}

StationCounts StationCounts::of(const station::StartupResult& result) {
    StationCounts counts;
    if (result.locomotives)
        for (const auto& loco : result.locomotives->locomotives)
            counts.locomotives += loco.isEmpty() ? 0 : 1;
    if (result.accessories)
        counts.accessories = int(result.accessories->accessories.size());
    if (result.routes)
        counts.routes = int(result.routes->routes.size());
    counts.pages = int(result.pages.size());
    counts.devices = int(result.devices.size());
    return counts;
}

StationConnection::StationConnection(ConnectionSettings settings, QObject* parent)
    : QObject(parent), settings_(std::move(settings)) {}

StationConnection::~StationConnection() {
    if (link_)
        link_->detach(this);
    link_.reset();
}

void StationConnection::connectTo(const QString& url) {
    disconnectFromStation();
    const QString address = url.trimmed();
    address_ = address;
    if (address.isEmpty()) {
        endpoint_ = StationEndpoint::simulated();
        if (!settings_.localStation)
            return fail(QStringLiteral("this program has no simulated station"));
        std::unique_ptr<transport::LocalPeer> local = settings_.localStation();
        if (!local->start())
            return fail(QStringLiteral("the simulated station cannot start: %1").arg(local->errorString()));
        const transport::TransportSettings address = local->address();
        link_ = std::make_unique<StationLink>();
        link_->local = std::move(local);
        return open(transport::createTransport(address));
    }
    const auto settings = transport::parseTransportUrl(address);
    if (!settings) {
        endpoint_ = StationEndpoint::unusable(address);
        return fail(settings.error());
    }
    endpoint_ = StationEndpoint::of(settings.value());
    link_ = std::make_unique<StationLink>();
    open(transport::createTransport(settings.value()));
}

// Ends the connection; its parts go at the next turn of the event loop, since this may be called from
// inside one of their signals.
void StationConnection::disconnectFromStation() {
    if (link_) {
        link_->detach(this);
        if (link_->session)
            link_->session->liveness().stop();
        link_->transport->close();
        link_.release()->deleteLater();
    }
    address_.clear();
    progress_ = {};
    result_ = {};
    failure_.clear();
    lastProblem_.clear();
    everConnected_ = lost_ = silent_ = loading_ = loaded_ = reload_ = false;
    updateState();
}

std::uint16_t StationConnection::embeddedPort() const {
    if (!link_ || !link_->local)
        return 0;
    const transport::TransportSettings address = link_->local->address();
    const auto* tcp = std::get_if<transport::TcpSettings>(&address);
    return tcp ? tcp->port : 0;
}

transport::TransportCounters StationConnection::transportCounters() const {
    return link_ && link_->transport ? link_->transport->counters() : transport::TransportCounters{};
}

station::StationSession* StationConnection::session() const {
    return link_ ? link_->session.get() : nullptr;
}

void StationConnection::open(std::unique_ptr<transport::Transport> transport) {
    link_->transport = std::move(transport);
    link_->session = std::make_unique<station::StationSession>(*link_->transport, settings_.session);
    watchTransport();
    updateState();
    emit sessionStarted(link_->session.get());
    link_->transport->open();
}

void StationConnection::fail(const QString& reason) {
    failure_ = reason;
    updateState();
    report(QStringLiteral("%1: %2").arg(description(), reason));
}

void StationConnection::watchTransport() {
    connect(link_->transport.get(), &transport::Transport::stateChanged, this,
            &StationConnection::transportStateChanged);
    connect(link_->transport.get(), &transport::Transport::problem, this, &StationConnection::report);
    connect(link_->transport.get(), &transport::Transport::framesReceived, this,
            [this](const std::vector<can::CanFrame>& frames) { emit framesSeen(frames, false); });
    connect(link_->transport.get(), &transport::Transport::framesSent, this,
            [this](const std::vector<can::CanFrame>& frames) { emit framesSeen(frames, true); });
    station::Liveness& liveness = link_->session->liveness();
    connect(&liveness, &station::Liveness::stationSilent, this, &StationConnection::stationSilent);
    connect(&liveness, &station::Liveness::stationRecovered, this, &StationConnection::stationRecovered);
}

void StationConnection::transportStateChanged(transport::Transport::State state) {
    using TransportState = transport::Transport::State;
    if (state == TransportState::Connected) {
        lost_ = false;
        link_->session->liveness().start();
        if (!everConnected_) {
            everConnected_ = true;
            runStartup();
        } else {
            reloadWhenPossible();
        }
    } else if (state == TransportState::Reconnecting && everConnected_) {
        lost_ = true;
        reload_ = true;
        loading_ = false; // the session abandoned the start-up that was running
        link_->session->liveness().stop();
    }
    updateState();
}

void StationConnection::stationSilent() {
    silent_ = true;
    reload_ = true;
    report(QStringLiteral("%1: the station stopped answering").arg(description()));
    updateState();
}

void StationConnection::stationRecovered() {
    silent_ = false;
    reloadWhenPossible();
    updateState();
}

// The start-up again, once the station answers and the previous start-up has finished.
void StationConnection::reloadWhenPossible() {
    if (!reload_ || lost_ || silent_ || loading_)
        return;
    reload_ = false;
    runStartup();
}

void StationConnection::runStartup() {
    if (link_->startup)
        link_->startup.release()->deleteLater(); // finished; it may be the sender of the current signal
    link_->startup = std::make_unique<station::StartupSequence>(*link_->session, settings_.startup);
    station::StartupSequence* startup = link_->startup.get();
    connect(startup, &station::StartupSequence::stepStarted, this, &StationConnection::startupStep);
    connect(startup, &station::StartupSequence::downloadProgress, this, &StationConnection::downloadProgress);
    connect(startup, &station::StartupSequence::problem, this, &StationConnection::report);
    connect(startup, &station::StartupSequence::ready, this, &StationConnection::startupReady);
    loading_ = true;
    progress_ = {};
    updateState();
    startup->start();
}

void StationConnection::startupStep(station::StartupSequence::Step step, int number, int count) {
    progress_ = {};
    progress_.step = loadingStep(step);
    progress_.stepNumber = number;
    progress_.stepCount = count;
    emit progressChanged(progress_);
}

void StationConnection::downloadProgress(const QString& key, qsizetype received, qsizetype announced,
                                         int file, int files) {
    const std::string name = cs2config::fileNameForKey(key.toStdString());
    progress_.file = name.empty() ? key : QString::fromStdString(name);
    progress_.received = received;
    progress_.announced = announced;
    progress_.fileNumber = file;
    progress_.fileCount = files;
    emit progressChanged(progress_);
}

// A start-up during which the station fell silent read nothing reliable: it runs again once the station
// answers, and its result is not passed on as the station's state.
void StationConnection::startupReady(const station::StartupResult& result) {
    if (silent_ || lost_) {
        loading_ = false;
        reload_ = true;
        reloadWhenPossible();
        updateState();
        return;
    }
    result_ = result;
    loading_ = false;
    loaded_ = true;
    emit configurationLoaded(result_);
    reloadWhenPossible();
    updateState();
}

void StationConnection::report(const QString& message) {
    lastProblem_ = message;
    emit problem(message);
}

void StationConnection::updateState() {
    const State state = evaluate();
    if (state == state_)
        return;
    state_ = state;
    emit stateChanged(state_);
}

StationConnection::State StationConnection::evaluate() const {
    if (!failure_.isEmpty())
        return State::Failed;
    if (!link_)
        return State::Disconnected;
    if (!everConnected_)
        return State::Connecting;
    if (lost_ || silent_)
        return State::Silent;
    if (loading_ || !loaded_)
        return State::LoadingConfiguration;
    return State::Ready;
}

} // namespace stellwerk::connection
