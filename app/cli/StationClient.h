#pragma once

#include "base/Expected.h"
#include "station/StationSession.h"
#include "transport/Transport.h"

#include <QEventLoop>
#include <QObject>
#include <QString>
#include <chrono>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

namespace stellwerk::cli {

// Exit statuses of the station commands.
enum StationExit : int { Acknowledged = 0, NotAcknowledged = 1, UsageError = 2, CannotOpen = 3 };

class StationClient;

// What one station command does once the station is reachable: `start` begins the work and, when it is
// done, calls client.finish(status). `limit` ends a command that takes longer (status 1).
struct StationJob {
    std::function<void(StationClient& client)> start;
    std::optional<std::chrono::milliseconds> limit;
};
using ParsedJob = Expected<StationJob, std::string>;

// How patient the command line is with a station.
struct ClientSettings {
    std::chrono::milliseconds connectTimeout{3000};
    station::CommandPolicy commands{std::chrono::milliseconds(500), 2};
};

// A command-line tool has no main window to keep the event loop going: this opens the transport,
// holds the station session and turns the event loop until the command says it is done.
class StationClient final : public QObject {
    Q_OBJECT

public:
    explicit StationClient(std::ostream& err, ClientSettings settings = {}, QObject* parent = nullptr);
    ~StationClient() override;

    // Creates the transport for `url` and waits until it is connected. Returns 0, UsageError for an
    // address that cannot be read, CannotOpen when the transport reports a problem or does not connect.
    int connectTo(const QString& url);
    // Starts the job and turns the event loop until it finishes or its limit passes.
    int run(const StationJob& job);
    void finish(int status);
    // Ctrl-C (SIGINT) ends the command with `status` instead of killing the process.
    void finishOnInterrupt(int status);
    // Ctrl-C (SIGINT) runs `action` instead (which finishes the command when it is done).
    void whenInterrupted(std::function<void()> action);

    station::StationSession& session() { return *session_; }
    bus::Bus& bus() { return *bus_; }
    transport::Transport& transport() { return *transport_; }
    const ClientSettings& settings() const { return settings_; }

private:
    int waitForConnection();
    void report(const QString& message);
    void watchInterrupt(int status);

    std::ostream& err_;
    ClientSettings settings_;
    std::unique_ptr<transport::Transport> transport_;
    std::unique_ptr<bus::Bus> bus_;
    std::unique_ptr<station::StationSession> session_;
    QEventLoop loop_;
    std::optional<int> status_;
    int lastStatus_ = Acknowledged; // of the last connect or command
    QString problem_;
    bool retryNoteFollows_ = false; // the next problem() repeats a connectionFailed() with a retry plan
};

} // namespace stellwerk::cli
