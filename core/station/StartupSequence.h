#pragma once

#include "cs2/Messages.h"
#include "cs2config/AccessoryFile.h"
#include "cs2config/LocomotiveFile.h"
#include "cs2config/RouteFile.h"
#include "cs2config/TrackPage.h"
#include "cs2config/TrackPlan.h"
#include "station/ConfigDownload.h"
#include "station/DeviceDescription.h"

#include <QObject>
#include <QStringList>
#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QTimer;

namespace stellwerk::station {

class StationSession;
class StateQueryRound;

// What the start-up does, and how long it listens for ping answers.
struct StartupOptions {
    std::chrono::milliseconds deviceWindow{500};
    bool wakeGleisbox = false; // a bare Gleisbox needs 0x1B "go" and system 0x08 (field notes)
    bool readStatusData = true;
    bool downloadConfiguration = true;
    bool queryStates = true;
    int queriesInFlight = 8; // state queries sent before the first answers arrive
};

// One page of the downloaded track plan.
struct DownloadedPage {
    std::int64_t id = 0;
    std::string name;
    cs2config::TrackPage page;
};

// Everything the start-up learned; what is missing is said in `problems`.
struct StartupResult {
    std::vector<DeviceDescription> devices;
    std::map<std::string, std::string> files; // key ("loks", "gbs-0") -> contents
    std::optional<cs2config::LocomotiveFile> locomotives;
    std::optional<cs2config::AccessoryFile> accessories;
    std::optional<cs2config::RouteFile> routes;
    std::optional<cs2config::TrackPlan> trackPlan;
    std::vector<DownloadedPage> pages;
    std::size_t stateQueries = 0;
    std::size_t stateAnswers = 0;
    QStringList problems;
};

// Brings a session from "connected" to "ready": lists the devices (ping), optionally wakes a Gleisbox,
// reads every device's status data, downloads locos, accessories, routes and the track plan pages,
// then asks for the current states (speed, direction, functions, the S88 contacts on the plan). Every
// step tolerates missing devices and files: they are reported, never fatal.
class StartupSequence final : public QObject {
    Q_OBJECT

public:
    enum class Step { Devices, WakeUp, StatusData, Configuration, States, Ready };
    Q_ENUM(Step)
    static constexpr int StepCount = 5;

    StartupSequence(StationSession& session, StartupOptions options = {}, QObject* parent = nullptr);
    ~StartupSequence() override;

    void start();
    // Stops here for good: nothing more is sent and ready() is not emitted. Happens by itself when the
    // session loses its connection (a start-up cut short must not pass for the station's state).
    void abandon();
    bool abandoned() const { return abandoned_; }
    const StartupResult& result() const { return result_; }
    Step step() const { return step_; }

signals:
    void stepStarted(stellwerk::station::StartupSequence::Step step, int number, int count);
    // The file being downloaded, its bytes so far and announced, and which file of how many.
    void downloadProgress(const QString& key, qsizetype received, qsizetype announced, int file, int files);
    void problem(const QString& message);
    void ready(const stellwerk::station::StartupResult& result);

private:
    void enter(Step step);
    void devicesListed();
    void wakeUp();
    void readNextDevice();
    void downloadNext();
    void fileArrived(const std::string& key, const DownloadResult& result);
    void keep(const std::string& key, const std::string& contents);
    void queueStateQueries();
    void report(const QString& message);

    StationSession& session_;
    StartupOptions options_;
    Step step_ = Step::Devices;
    StartupResult result_;
    QTimer* windowTimer_;
    std::size_t nextDevice_ = 0;
    std::deque<std::string> keys_;
    int filesDone_ = 0;
    std::unique_ptr<StateQueryRound> queries_;
    bool abandoned_ = false;
};

} // namespace stellwerk::station
