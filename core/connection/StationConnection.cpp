#include "connection/StationConnection.h"

#include "connection/StationAddress.h"
#include "connection/StationLink.h"
#include "cs2config/ConfigStreamKeys.h"
#include "transport/TransportAddress.h"
#include "transport/TransportFactory.h"

namespace stellwerk::connection {

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
    : QObject(parent), settings_(std::move(settings)), buses_(new ConnectionBuses(this)),
      devices_(new ConnectionDevices(settings_.devices, settings_.localStationDevices, this)),
      handhelds_(new ConnectionHandhelds(settings_.handhelds, this)),
      pictures_(new LocomotivePictures(settings_.pictures, this)) {
    connect(devices_, &ConnectionDevices::problem, this, &StationConnection::report);
}

// The faces let go of the link without a word: nobody is told about a connection that goes with its owner.
StationConnection::~StationConnection() {
    if (!link_)
        return;
    link_->detach(this);
    for (QObject* face : std::initializer_list<QObject*>{buses_, devices_, handhelds_})
        face->blockSignals(true);
    buses_->release();
    devices_->release();
    handhelds_->release();
    link_.reset();
}

void StationConnection::connectTo(const QString& url, const QStringList& furtherBuses) {
    disconnectFromStation();
    address_ = url.trimmed();
    furtherBuses_ = furtherBuses;
    link_ = std::make_unique<StationLink>();
    auto station = stationTransport();
    if (!station) {
        link_.reset();
        return fail(station.error());
    }
    std::vector<transport::TransportSettings> further;
    if (devices_->choose(link_->local != nullptr))
        further = link_->local->deviceBuses();
    for (const QString& address : furtherBuses) {
        const auto settings = furtherBusSettings(address);
        if (!settings) {
            link_.reset();
            return fail(settings.error());
        }
        further.push_back(settings.value());
    }
    open(std::move(station.value()), further);
}

// The transport to the station at address_, or to the local station (started here) when there is none.
Expected<std::unique_ptr<transport::Transport>, QString> StationConnection::stationTransport() {
    if (address_.isEmpty()) {
        endpoint_ = StationEndpoint::simulated();
        if (!settings_.localStation)
            return QStringLiteral("this program has no simulated station");
        std::unique_ptr<transport::LocalPeer> local = settings_.localStation();
        if (!local->start())
            return QStringLiteral("the simulated station cannot start: %1").arg(local->errorString());
        const transport::TransportSettings address = local->address();
        pictures_->setStation(local->webAddress());
        link_->local = std::move(local);
        return transport::createTransport(address);
    }
    const auto split = StationAddress::split(address_);
    const auto settings = split ? transport::parseTransportUrl(split->transport)
                                : Expected<transport::TransportSettings, QString>(
                                      QStringLiteral("'%1': %2").arg(address_, split.error()));
    if (!settings) {
        endpoint_ = StationEndpoint::unusable(address_);
        return QString(settings.error());
    }
    endpoint_ = StationEndpoint::of(settings.value());
    pictures_->setStation(StationAddress::webServerOf(address_));
    return transport::createTransport(settings.value());
}

Expected<transport::TransportSettings, QString>
StationConnection::furtherBusSettings(const QString& address) {
    const auto settings = transport::parseTransportUrl(address.trimmed());
    if (!settings)
        return QStringLiteral("further bus \"%1\": %2").arg(address.trimmed(), settings.error());
    return settings.value();
}

// Ends the connection; its parts go at the next turn of the event loop, since this may be called from
// inside one of their signals.
void StationConnection::disconnectFromStation() {
    if (link_) {
        link_->detach(this); // closing the transports below tears the device sessions down
        devices_->release();
        if (link_->session)
            link_->session->liveness().stop();
        for (const auto& transport : link_->transports)
            transport->close();
        link_.release()->deleteLater();
    }
    address_.clear();
    furtherBuses_.clear();
    pictures_->setStation({});
    progress_ = {};
    result_ = {};
    failure_.clear();
    lastProblem_.clear();
    everConnected_ = lost_ = silent_ = loading_ = loaded_ = reload_ = false;
    updateState();
    buses_->release();
    handhelds_->release();
}

std::uint16_t StationConnection::embeddedPort() const {
    if (!link_ || !link_->local)
        return 0;
    const transport::TransportSettings address = link_->local->address();
    const auto* tcp = std::get_if<transport::TcpSettings>(&address);
    return tcp ? tcp->port : 0;
}

station::StationSession* StationConnection::session() const {
    return link_ ? link_->session.get() : nullptr;
}

void StationConnection::open(std::unique_ptr<transport::Transport> station,
                             const std::vector<transport::TransportSettings>& further) {
    const DeviceSettings& devices = devices_->active();
    link_->addBus(std::move(station), deviceBusProfile(devices, 0, busreading::BusProfile::centralStation()),
                  endpoint_.place);
    for (const transport::TransportSettings& settings : further)
        link_->addBus(transport::createTransport(settings),
                      deviceBusProfile(devices, int(link_->buses.size()), settings_.furtherBusProfile),
                      StationEndpoint::of(settings).place);
    link_->session = std::make_unique<station::StationSession>(link_->stationBus(), settings_.session);
    watchTransport();
    watchBusProblems();
    handhelds_->open(*link_);
    devices_->open(*link_);
    buses_->follow(*link_);
    updateState();
    emit sessionStarted(link_->session.get());
    for (const auto& transport : link_->transports)
        transport->open();
}

void StationConnection::fail(const QString& reason) {
    failure_ = reason;
    updateState();
    report(QStringLiteral("%1: %2").arg(description(), reason));
}

void StationConnection::watchTransport() {
    transport::Transport* station = &link_->stationTransport();
    connect(station, &transport::Transport::stateChanged, this, &StationConnection::transportStateChanged);
    station::Liveness& liveness = link_->session->liveness();
    connect(&liveness, &station::Liveness::stationSilent, this, &StationConnection::stationSilent);
    connect(&liveness, &station::Liveness::stationRecovered, this, &StationConnection::stationRecovered);
}

// The problems of every bus for the person (a further bus that goes away does not change the station's
// state: its transport tries again by itself).
void StationConnection::watchBusProblems() {
    for (const auto& transport : link_->transports)
        connect(transport.get(), &transport::Transport::problem, this, &StationConnection::report);
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
    link_->handhelds->devicesListed(result_.devices);
    pictures_->retryFailed(); // the station answers again: what failed while it was away may be there
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
