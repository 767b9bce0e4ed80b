// The Z21 server in front of a railway on the simulated CS2 (issue 35), everything over real loopback
// sockets: Z21 clients of the bench's own (UDP) -> Z21Server -> Railway -> StationSession -> TCP ->
// StationServer -> SimulatedStation, and the station's answer back the same way as the client's loco info.
//   1. latency: one client's LAN_X_SET_LOCO_DRIVE to its LAN_X_LOCO_INFO showing the step the station
//      acknowledged (target p99 < 5 ms),
//   2. load: 50 clients each sending 20 drive commands a second for 10 s, each on its own locomotive: sent,
//      answered, lost, and the largest queues seen (commands waiting for the station's acknowledgement,
//      drives not yet answered to their client), in the first and in the second half of the run.
// A plain harness printing figures: each measurement runs the Qt event loop, which Google Benchmark's loop
// does not fit. Run: build/bench/stellwerk-phone-bench [latency samples] [clients] [seconds]

#include "model/Railway.h"
#include "model/Z21Addresses.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "station/StartupSequence.h"
#include "station/StationSession.h"
#include "transport/TcpTransport.h"
#include "z21/ReplyCodec.h"
#include "z21/RequestCodec.h"
#include "z21server/Z21Server.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLoggingCategory>
#include <QNetworkDatagram>
#include <QTimer>
#include <QUdpSocket>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace {

using namespace stellwerk;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr int LocomotiveCount = 50; // DCC 1..50: every client of the load drives its own

// Runs the event loop as an application does (sleeping until the next event) until `done` holds or the
// time is up; returns whether it holds.
bool runUntil(const std::function<bool()>& done, std::chrono::milliseconds limit) {
    QElapsedTimer clock;
    clock.start();
    QTimer tick; // wakes the loop to look at the clock
    tick.start(10);
    while (!done() && clock.elapsed() < limit.count())
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    return done();
}

double percentile(std::vector<double> values, double p) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const auto index = std::size_t(p * double(values.size() - 1) + 0.5);
    return values[std::min(index, values.size() - 1)];
}

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// 50 DCC locomotives on addresses 1..50 (Loc-ID 0xC000 + address): on the Z21 they keep their address.
sim::StationLayout locomotives() {
    std::string file = "[lokomotive]\nversion\n .minor=3\n";
    for (int address = 1; address <= LocomotiveCount; ++address) {
        char uid[8];
        std::snprintf(uid, sizeof uid, "0x%x", 0xC000 + address);
        file += "lokomotive\n .name=Lok " + std::to_string(address) + "\n .uid=" + uid +
                "\n .adresse=" + std::to_string(address) + "\n .typ=dcc\n";
    }
    return sim::StationLayout::fromFiles({{"lokomotive.cs2", file}});
}

// A 128-step drive to a step; the station's speed it selects, read back as a step, is the step itself.
z21::SetLocoDrive driveTo(std::uint16_t address, std::uint8_t step) {
    return z21::SetLocoDrive{address, {z21::SpeedStepMode::Steps128, true, step, false}};
}

// The simulated station on 127.0.0.1 (TCP, a free port), the app's session and railway on it as the
// command line's `serve` holds them, and the Z21 server in front (UDP, a free port).
class ServedStation {
public:
    ServedStation() : station_(locomotives()) {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udp = false;
        settings.tcpPort = 0;
        settings.announcePowerToNewClients = true;
        server_ = std::make_unique<sim::StationServer>(station_, settings);
        listening_ = server_->listen();
        transport_ = std::make_unique<transport::TcpTransport>(
            transport::TcpSettings{"127.0.0.1", server_->tcpPort(), transport::ReconnectTiming{}});
        bus_ = std::make_unique<bus::Bus>(*transport_, busreading::BusProfile::centralStation());
        session_ = std::make_unique<station::StationSession>(*bus_, station::StationSettings{});
        railway_ = std::make_unique<model::Railway>(*session_);
        z21server::Z21ServerOptions options;
        options.address = QHostAddress::LocalHost;
        options.port = 0;
        z21_ = std::make_unique<z21server::Z21Server>(addresses_, options);
    }
    ~ServedStation() {
        z21_.reset();
        railway_.reset();
        session_.reset();
        bus_.reset();
        transport_.reset();
    }

    // Connects, reads the station's state into the railway and opens the Z21 server.
    bool start() {
        if (!listening_ || !z21_->listen())
            return false;
        station::StartupSequence startup(*session_);
        QObject::connect(&startup, &station::StartupSequence::ready, railway_.get(),
                         [this](const station::StartupResult& result) { railway_->load(result); });
        transport_->open();
        startup.start();
        if (!runUntil([&] { return railway_->isStateReported(); }, 10000ms))
            return false;
        z21_->setRailway(railway_.get());
        return true;
    }

    quint16 z21Port() const { return z21_->port(); }
    std::size_t stationQueue() const { return session_->tracker().pendingCount(); }
    const z21server::Z21Counters& counters() const { return z21_->counters(); }
    std::uint64_t retries() const { return session_->tracker().retriesSent(); }

private:
    sim::SimulatedStation station_;
    std::unique_ptr<sim::StationServer> server_;
    std::unique_ptr<transport::TcpTransport> transport_;
    std::unique_ptr<bus::Bus> bus_;
    std::unique_ptr<station::StationSession> session_;
    std::unique_ptr<model::Railway> railway_;
    model::Z21Addresses addresses_;
    std::unique_ptr<z21server::Z21Server> z21_;
    bool listening_ = false;
};

// A Z21 client of the bench's own on a loopback port: it sends requests and hands every loco info it
// reads to `onLocoInfo`.
class PhoneClient {
public:
    explicit PhoneClient(quint16 serverPort) : serverPort_(serverPort) {
        socket_.bind(QHostAddress::LocalHost, 0);
        QObject::connect(&socket_, &QUdpSocket::readyRead, &socket_, [this] { read(); });
        send(z21::SetBroadcastFlags{z21::broadcast::DrivingAndSwitching});
    }

    void send(const z21::RequestBody& request) {
        const std::vector<std::uint8_t> bytes = z21::encodeRequest(request);
        socket_.writeDatagram(reinterpret_cast<const char*>(bytes.data()), qint64(bytes.size()),
                              QHostAddress::LocalHost, serverPort_);
    }

    std::function<void(const z21::LocoInfo&)> onLocoInfo;

private:
    void read() {
        while (socket_.hasPendingDatagrams()) {
            const QByteArray data = socket_.receiveDatagram().data();
            const z21::DatagramReplies replies = z21::readReplies(
                std::span(reinterpret_cast<const std::uint8_t*>(data.constData()), std::size_t(data.size())));
            for (const z21::Reply& reply : replies.replies)
                if (const auto* info = std::get_if<z21::LocoInfo>(&reply); info && onLocoInfo)
                    onLocoInfo(*info);
        }
    }

    QUdpSocket socket_;
    quint16 serverPort_;
};

// ---- 1. Latency ---------------------------------------------------------------------------------------

// One drive: milliseconds from sending it to the loco info showing its step; negative when none came.
double driveLatency(PhoneClient& phone, std::uint8_t step) {
    bool shown = false;
    phone.onLocoInfo = [&](const z21::LocoInfo& info) {
        shown = shown || (info.address == 1 && info.speed.step == step);
    };
    const auto start = Clock::now();
    phone.send(driveTo(1, step));
    const bool answered = runUntil([&] { return shown; }, 2000ms);
    const double ms = millisecondsSince(start);
    phone.onLocoInfo = nullptr;
    return answered ? ms : -1.0;
}

// One drive every 10 ms (100 a second, half the server's flood limit per client; a phone sends far fewer).
std::vector<double> pacedDrives(PhoneClient& phone, int count, int& lost) {
    std::vector<double> times;
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < count; ++i) {
        runUntil([&] { return clock.elapsed() >= qint64(i) * 10; }, 1000ms);
        const double ms = driveLatency(phone, std::uint8_t(2 + i % 120));
        ms < 0 ? void(++lost) : times.push_back(ms);
    }
    return times;
}

void benchLatency(int count) {
    ServedStation served;
    if (!served.start())
        return void(std::printf("drive latency: the station or the Z21 server did not start\n"));
    PhoneClient phone(served.z21Port());
    int lost = 0;
    pacedDrives(phone, 100, lost); // warm-up: the loco's first drive, caches, socket buffers
    lost = 0;
    const std::vector<double> times = pacedDrives(phone, count, lost);
    if (times.empty())
        return void(std::printf("drive latency: no drive answered\n"));
    std::printf("z21 drive -> acknowledged speed: %zu drives, p50 %.3f ms, p99 %.3f ms, max %.3f ms "
                "(unanswered %d, flood-limited %llu, station retries %llu)  p99 target < 5 ms: %s\n",
                times.size(), percentile(times, 0.5), percentile(times, 0.99),
                *std::max_element(times.begin(), times.end()), lost,
                static_cast<unsigned long long>(served.counters().limited),
                static_cast<unsigned long long>(served.retries()),
                percentile(times, 0.99) < 5.0 && lost == 0 ? "met" : "MISSED");
}

// ---- 2. Load -------------------------------------------------------------------------------------------

// One client of the load on its own locomotive (its number + 1): its drives, each with a step other than
// the one before, and those its loco info has not shown yet.
struct LoadClient {
    explicit LoadClient(quint16 serverPort, std::uint16_t address) : phone(serverPort), address(address) {
        phone.onLocoInfo = [this](const z21::LocoInfo& info) { answer(info); };
    }
    void drive() {
        const auto step = std::uint8_t(2 + sent % 120);
        waiting[step] = Clock::now();
        phone.send(driveTo(address, step));
        ++sent;
    }
    void answer(const z21::LocoInfo& info) {
        const auto found = waiting.find(info.speed.step);
        if (info.address != address || found == waiting.end())
            return;
        latencies.push_back(millisecondsSince(found->second));
        waiting.erase(found);
        ++answered;
    }

    PhoneClient phone;
    std::uint16_t address;
    std::map<std::uint8_t, Clock::time_point> waiting;
    std::vector<double> latencies;
    int sent = 0;
    int answered = 0;
};

// The largest queues seen: commands the station has not acknowledged, drives not yet answered.
struct Queues {
    std::size_t station = 0;
    std::size_t unanswered = 0;
};

struct LoadRun {
    std::vector<std::unique_ptr<LoadClient>> clients;
    Queues firstHalf;
    Queues secondHalf;
};

// Every client sends its drives on its own phase (spread over the 50 ms between two of its drives), as
// many as are due by now; the queues are looked at on every tick.
void loadTick(LoadRun& run, ServedStation& served, qint64 elapsedMs, int perSecond, int totalPerClient,
              bool firstHalf) {
    const qint64 period = 1000 / perSecond;
    for (std::size_t i = 0; i < run.clients.size(); ++i) {
        LoadClient& client = *run.clients[i];
        const qint64 phase = qint64(i) * period / qint64(run.clients.size());
        const auto due =
            elapsedMs < phase ? 0 : int(std::min<qint64>(totalPerClient, (elapsedMs - phase) / period + 1));
        while (client.sent < due)
            client.drive();
    }
    std::size_t unanswered = 0;
    for (const auto& client : run.clients)
        unanswered += client->waiting.size();
    Queues& half = firstHalf ? run.firstHalf : run.secondHalf;
    half.station = std::max(half.station, served.stationQueue());
    half.unanswered = std::max(half.unanswered, unanswered);
}

void printLoad(const LoadRun& run, const ServedStation& served, int seconds, double wallSeconds) {
    int sent = 0;
    int answered = 0;
    std::vector<double> latencies;
    for (const auto& client : run.clients) {
        sent += client->sent;
        answered += client->answered;
        latencies.insert(latencies.end(), client->latencies.begin(), client->latencies.end());
    }
    const bool held = sent == answered && run.secondHalf.unanswered <= run.firstHalf.unanswered + 1 &&
                      run.secondHalf.station <= run.firstHalf.station + 1;
    std::printf("z21 load: %zu clients x %d drives/s for %d s (%.2f s): sent %d, answered %d, lost %d; "
                "answer p50 %.3f ms, p99 %.3f ms, max %.3f ms; largest queue at the station %zu then %zu "
                "commands, unanswered drives %zu then %zu (first half, second half); flood-limited %llu, "
                "refused %llu, station retries %llu  target no loss, no growing queue: %s\n",
                run.clients.size(), sent / std::max<int>(1, int(run.clients.size())) / seconds, seconds,
                wallSeconds, sent, answered, sent - answered, percentile(latencies, 0.5),
                percentile(latencies, 0.99),
                latencies.empty() ? 0.0 : *std::max_element(latencies.begin(), latencies.end()),
                run.firstHalf.station, run.secondHalf.station, run.firstHalf.unanswered,
                run.secondHalf.unanswered, static_cast<unsigned long long>(served.counters().limited),
                static_cast<unsigned long long>(served.counters().refused),
                static_cast<unsigned long long>(served.retries()), held ? "met" : "MISSED");
}

void benchLoad(int clientCount, int perSecond, int seconds) {
    ServedStation served;
    if (!served.start())
        return void(std::printf("z21 load: the station or the Z21 server did not start\n"));
    LoadRun run;
    for (int i = 0; i < clientCount; ++i)
        run.clients.push_back(
            std::make_unique<LoadClient>(served.z21Port(), std::uint16_t(1 + i % LocomotiveCount)));
    const int totalPerClient = perSecond * seconds;
    QElapsedTimer clock;
    clock.start();
    QTimer tick;
    tick.setTimerType(Qt::PreciseTimer);
    QObject::connect(&tick, &QTimer::timeout, &tick, [&] {
        const qint64 elapsed = clock.elapsed();
        loadTick(run, served, elapsed, perSecond, totalPerClient, elapsed < seconds * 500);
    });
    tick.start(2);
    const auto allSent = [&] {
        return std::all_of(run.clients.begin(), run.clients.end(),
                           [&](const auto& client) { return client->sent == totalPerClient; });
    };
    runUntil(allSent, std::chrono::milliseconds(seconds * 1000 + 5000));
    const double wallSeconds = double(clock.elapsed()) / 1000.0;
    tick.stop();
    runUntil(
        [&] {
            return std::all_of(run.clients.begin(), run.clients.end(),
                               [](const auto& client) { return client->waiting.empty(); });
        },
        2000ms); // the last drives' answers
    printLoad(run, served, seconds, wallSeconds);
}

} // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("stellwerk.*.info=false"));
    const int samples = argc > 1 ? std::atoi(argv[1]) : 1000;
    const int clients = argc > 2 ? std::atoi(argv[2]) : 50;
    const int seconds = argc > 3 ? std::atoi(argv[3]) : 10;
    benchLatency(samples);
    benchLoad(clients, 20, seconds);
    return 0;
}
