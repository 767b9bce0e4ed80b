#pragma once

#include "base/Expected.h"
#include "busreading/FrameClassifier.h"
#include "connection/ConnectionBuses.h"
#include "connection/ConnectionDevices.h"
#include "connection/ConnectionHandhelds.h"
#include "connection/DeviceSettings.h"
#include "connection/HandheldConnection.h"
#include "connection/LocomotivePictures.h"
#include "connection/StationEndpoint.h"
#include "station/StartupSequence.h"
#include "station/StationSession.h"
#include "transport/LocalPeer.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <memory>
#include <optional>
#include <vector>

namespace stellwerk::connection {

class StationLink;

// What the start-up is doing, in a person's words.
enum class LoadingStep { ListingDevices, WakingUp, ReadingDevices, DownloadingFiles, ReadingStates };

// How far loading the configuration has come: step n of m, and the file being downloaded.
struct LoadingProgress {
    LoadingStep step = LoadingStep::ListingDevices;
    int stepNumber = 0;
    int stepCount = station::StartupSequence::StepCount;
    QString file; // "lokomotive.cs2" while a file downloads, else empty
    int fileNumber = 0;
    int fileCount = 0;
    qsizetype received = 0;
    qsizetype announced = 0; // 0 until the station announced the size

    // Percent of the current file, when its size is known.
    std::optional<int> percent() const;
};

// What the station's configuration holds, once loaded.
struct StationCounts {
    int locomotives = 0;
    int accessories = 0;
    int routes = 0;
    int pages = 0;
    int devices = 0;

    static StationCounts of(const station::StartupResult& result);
    friend bool operator==(const StationCounts&, const StationCounts&) = default;
};

// How patient the connection is; the defaults suit a CS2 on a LAN and the embedded simulator.
// localStation is the station this program runs itself (the GUI program and tests hand over the embedded
// simulated CS2); without one, connecting to "the simulated station" fails with a clear reason.
// furtherBusProfile: the protocols expected on the further buses besides the devices' (none by default:
// a frame no device session claims is foreign: counted and shown, never read as a CS2 command).
// devices: which buses carry the OpenRailCAN central and which RO modules (see DeviceSessions).
struct ConnectionSettings {
    station::StationSettings session{};
    station::StartupOptions startup{};
    transport::LocalPeerFactory localStation{};
    busreading::BusProfile furtherBusProfile{};
    LocomotivePictures::Settings pictures{};
    HandheldSettings handhelds{};
    DeviceSettings devices{};
    // The devices of the local station (its deviceBuses() become buses 1.. before the further buses
    // given to connectTo()); used instead of `devices` when connected to it. None: it brings none.
    std::optional<DeviceSettings> localStationDevices{};
};

// The one object the app holds to be connected to a station. Given an address (udp://, tcp://, can://,
// see transport/TransportAddress.h) it opens the transport, runs the station session's start-up and
// watches liveness; given none it starts the program's local station (the embedded simulated CS2, from
// the settings' factory) and reaches it over a real transport. Further buses (a USB-CAN adapter wired to
// relay modules) are held open beside the station's; a bus that goes away is reported and reconnected by
// its transport without touching the station's state.
// Its state is in user terms; the model takes the session and the start-up result from here. What the
// panels need of the rest is handed out as faces, one job each: buses(), devices(), handhelds(), pictures().
// After the station was silent or the connection was lost, the start-up runs again (the station may
// have restarted, and others may have changed what we missed); a start-up cut short by a loss, or during
// which the station fell silent, is thrown away and never emitted as configurationLoaded.
class StationConnection final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(StationConnection)

public:
    enum class State { Disconnected, Connecting, LoadingConfiguration, Ready, Silent, Failed };
    Q_ENUM(State)

    explicit StationConnection(ConnectionSettings settings = {}, QObject* parent = nullptr);
    ~StationConnection() override;

    // Connects to the station at `url`; an empty url starts the local (simulated) station. Any
    // previous connection ends first. `furtherBuses` are more addresses to hold open beside it (bus 1, 2,
    // ...); when one of them cannot be read, nothing is opened and the connection fails with the reason.
    void connectTo(const QString& url, const QStringList& furtherBuses = {});
    void connectToSimulator() { connectTo(QString()); }
    void disconnectFromStation();

    State state() const { return state_; }
    // The address given to connectTo() (empty for the embedded station).
    const QString& address() const { return address_; }
    // The further buses' addresses given to connectTo().
    const QStringList& furtherBuses() const { return furtherBuses_; }
    const StationEndpoint& endpoint() const { return endpoint_; }
    QString description() const { return endpoint_.description(); }
    const LoadingProgress& progress() const { return progress_; }
    // What the last finished start-up found (empty counts before the first one finished).
    StationCounts counts() const { return StationCounts::of(result_); }
    const station::StartupResult& startupResult() const { return result_; }
    // The session while connected (also during the start-up), else null.
    station::StationSession* session() const;
    // Why the connection failed (state Failed), in English.
    QString failureReason() const { return failure_; }
    // The last problem reported (connection refused, a file that could not be read, ...).
    QString lastProblem() const { return lastProblem_; }
    // The local station's TCP port while it runs, else 0 (for diagnostics and tests).
    std::uint16_t embeddedPort() const;
    // The buses held open, their frames and counters: the bus monitor's face.
    ConnectionBuses& buses() const { return *buses_; }
    // The device sessions and the device settings: the devices panel's face.
    ConnectionDevices& devices() const { return *devices_; }
    // The MS1 handhelds' master and Stellwerk's role among them: the handhelds panel's face.
    ConnectionHandhelds& handhelds() const { return *handhelds_; }
    // The locomotives' pictures from the station's web server ("http://192.168.2.5", port 80 as on a CS2;
    // the port of the address's `?http=` option; the embedded station's own port; none over CAN), and the
    // open layout's icons folder.
    LocomotivePictures& pictures() const { return *pictures_; }

signals:
    void stateChanged(stellwerk::connection::StationConnection::State state);
    void progressChanged(const stellwerk::connection::LoadingProgress& progress);
    // Something a person should see; the state does not necessarily change.
    void problem(const QString& message);
    // A new session exists and its start-up is about to run: the moment to create the model.
    void sessionStarted(stellwerk::station::StationSession* session);
    // A start-up finished (the first one, and again after each reload): the moment to load the model.
    void configurationLoaded(const stellwerk::station::StartupResult& result);

private:
    Expected<std::unique_ptr<transport::Transport>, QString> stationTransport();
    static Expected<transport::TransportSettings, QString> furtherBusSettings(const QString& address);
    void open(std::unique_ptr<transport::Transport> station,
              const std::vector<transport::TransportSettings>& further);
    void fail(const QString& reason);
    void watchTransport();
    void watchBusProblems();
    void transportStateChanged(transport::Transport::State state);
    void stationSilent();
    void stationRecovered();
    void runStartup();
    void reloadWhenPossible();
    void startupStep(station::StartupSequence::Step step, int number, int count);
    void downloadProgress(const QString& key, qsizetype received, qsizetype announced, int file, int files);
    void startupReady(const station::StartupResult& result);
    void report(const QString& message);
    void updateState();
    State evaluate() const;

    ConnectionSettings settings_;
    ConnectionBuses* buses_;
    ConnectionDevices* devices_;
    ConnectionHandhelds* handhelds_;
    LocomotivePictures* pictures_;
    std::unique_ptr<StationLink> link_;
    QString address_;
    QStringList furtherBuses_;
    StationEndpoint endpoint_;
    State state_ = State::Disconnected;
    LoadingProgress progress_;
    station::StartupResult result_;
    QString failure_;
    QString lastProblem_;
    bool everConnected_ = false;
    bool lost_ = false;    // the transport lost its connection and is trying again
    bool silent_ = false;  // the station stopped answering pings
    bool loading_ = false; // a start-up runs
    bool loaded_ = false;  // a start-up finished
    bool reload_ = false;  // run the start-up again once the station is back
};

} // namespace stellwerk::connection
