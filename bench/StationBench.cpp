// The station session over real loopback sockets, against the simulated CS2 in the same process:
//   1. acknowledged-command round trip over TCP and UDP (send -> acknowledgement; target p99 < 2 ms),
//   2. frames per second a TcpTransport + StationSession absorb without loss (target >= 50,000/s,
//      about 25 times a saturated 250 kbit/s CAN bus),
//   3. config download of the corpus' largest lokomotive.cs2 over TCP (request -> complete file).
// A plain harness printing figures: each measurement runs the Qt event loop, which Google Benchmark's
// loop does not fit. Run: build/bench/stellwerk-station-bench [round-trip count] [frame count]

#include "cs2/Codec.h"
#include "cs2config/ConfigStreamRequest.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "station/StationSession.h"
#include "transport/NetworkFraming.h"
#include "transport/TcpTransport.h"
#include "transport/UdpTransport.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLoggingCategory>
#include <QTimer>
#include <QUdpSocket>
#include <algorithm>
#include <arpa/inet.h>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <netinet/in.h>
#include <string>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using namespace stellwerk;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr std::uint32_t MfxLoco = 0x4001;

// Runs the event loop as an application does (sleeping until the next event, no busy polling) until
// `done` holds or the time is up; returns whether it holds.
bool runUntil(const std::function<bool()>& done, std::chrono::milliseconds limit) {
    QElapsedTimer clock;
    clock.start();
    QTimer tick; // wakes the loop to look at the clock
    tick.start(10);
    while (!done() && clock.elapsed() < limit.count()) {
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    }
    return done();
}

double percentile(std::vector<double> sorted, double p) {
    std::sort(sorted.begin(), sorted.end());
    const auto index = std::size_t(p * double(sorted.size() - 1) + 0.5);
    return sorted[std::min(index, sorted.size() - 1)];
}

station::StationSettings sessionSettings() {
    station::StationSettings settings;
    settings.uid = 0x53574B01;
    return settings;
}

// The simulated station on 127.0.0.1 (free ports) and the app's transport and session.
struct Loopback {
    enum class Wire { Tcp, Udp };

    Loopback(Wire wire, sim::StationLayout layout) : station(std::move(layout)) {
        QUdpSocket probe; // a free port for the app's UDP side
        probe.bind(QHostAddress::LocalHost, 0);
        const std::uint16_t appUdpPort = probe.localPort();
        probe.close();
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udp = wire == Wire::Udp;
        settings.udpPort = 0;
        settings.udpReplyHost = QHostAddress::LocalHost;
        settings.udpReplyPort = appUdpPort;
        settings.tcp = wire == Wire::Tcp;
        settings.tcpPort = 0;
        server = std::make_unique<sim::StationServer>(station, settings);
        listening = server->listen();
        if (wire == Wire::Tcp)
            transport = std::make_unique<transport::TcpTransport>(
                transport::TcpSettings{"127.0.0.1", server->tcpPort(), transport::ReconnectTiming{}});
        else
            transport = std::make_unique<transport::UdpTransport>(
                transport::UdpSettings{"127.0.0.1", server->udpPort(), appUdpPort,
                                       QHostAddress(QHostAddress::LocalHost), transport::ReconnectTiming{}});
        bus = std::make_unique<bus::Bus>(*transport, busreading::BusProfile::centralStation());
        session = std::make_unique<station::StationSession>(*bus, sessionSettings());
        transport->open();
    }
    ~Loopback() {
        session.reset();
        bus.reset();
        transport.reset();
    }

    bool connected() {
        return listening &&
               runUntil([&] { return transport->state() == transport::Transport::State::Connected; }, 5000ms);
    }

    sim::SimulatedStation station;
    std::unique_ptr<sim::StationServer> server;
    std::unique_ptr<transport::Transport> transport;
    std::unique_ptr<bus::Bus> bus;
    std::unique_ptr<station::StationSession> session;
    bool listening = false;
};

// ---- 1. Round trip ------------------------------------------------------------------------------

// One speed command: microseconds from request() to the acknowledgement; negative when it failed.
double roundTrip(station::StationSession& session, std::uint16_t speed) {
    bool done = false;
    bool acknowledged = false;
    const auto start = Clock::now();
    auto end = start;
    session.request(cs2::Message{0, false, 0, cs2::LocoSpeed{cs2::LocId(MfxLoco), speed}},
                    [&](const station::CommandResult& result) {
                        end = Clock::now();
                        acknowledged = result.succeeded();
                        done = true;
                    });
    runUntil([&] { return done; }, 5000ms);
    return acknowledged ? std::chrono::duration<double, std::micro>(end - start).count() : -1.0;
}

void benchRoundTrip(Loopback::Wire wire, const char* name, int count) {
    Loopback loopback(wire, sim::StationLayout::demo());
    if (!loopback.connected()) {
        std::printf("round trip %-4s: could not connect\n", name);
        return;
    }
    for (int i = 0; i < 200; ++i) // warm-up: caches, the station's loco entry, socket buffers
        roundTrip(*loopback.session, std::uint16_t(i));
    std::vector<double> times;
    int failed = 0;
    for (int i = 0; i < count; ++i) {
        const double us = roundTrip(*loopback.session, std::uint16_t(i % 1001));
        us < 0 ? void(++failed) : times.push_back(us);
    }
    if (times.empty())
        return void(std::printf("round trip %-4s: no command acknowledged\n", name));
    std::printf("round trip %-4s: %zu acknowledged speed commands, p50 %7.1f us, p99 %7.1f us, max %8.1f us"
                "  (failed %d, retries %llu)  p99 target < 2000 us: %s\n",
                name, times.size(), percentile(times, 0.50), percentile(times, 0.99),
                *std::max_element(times.begin(), times.end()), failed,
                static_cast<unsigned long long>(loopback.session->tracker().retriesSent()),
                percentile(times, 0.99) < 2000.0 ? "met" : "MISSED");
}

// ---- 2. Frames per second ------------------------------------------------------------------------

// What a busy bus carries: S88 events (contacts 1..1000 occupied/free) and speed answers, mixed.
QByteArray busTraffic(std::size_t count) {
    std::vector<can::CanFrame> frames;
    frames.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const auto n = std::uint16_t(i % 1000);
        if (i % 2 == 0) {
            cs2::S88Change change{std::uint8_t((i / 2) % 2), std::uint8_t(1 - (i / 2) % 2), 10};
            frames.push_back(
                cs2::encode({0, true, 0x0B01,
                             cs2::S88Event{0, std::uint16_t(n + 1), std::nullopt, std::nullopt, change}}));
        } else {
            frames.push_back(cs2::encode({0, true, 0x2F11, cs2::LocoSpeed{cs2::LocId(0x4000 + n % 64), n}}));
        }
    }
    return transport::encodeFrames(frames);
}

// A peer that accepts one connection and writes everything as fast as the kernel takes it, on its own
// thread with a blocking POSIX socket so that sending costs the measured event loop nothing.
class Blaster {
public:
    explicit Blaster(QByteArray bytes) : bytes_(std::move(bytes)) {
        listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof address;
        ::bind(listener_, reinterpret_cast<sockaddr*>(&address), length);
        ::listen(listener_, 1);
        ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length);
        port_ = ntohs(address.sin_port);
        thread_ = std::thread([this] { blast(); });
    }
    ~Blaster() {
        thread_.join();
        ::close(listener_);
    }
    std::uint16_t port() const { return port_; }

private:
    void blast() {
        const int peer = ::accept(listener_, nullptr, nullptr);
        qsizetype sent = 0;
        while (peer >= 0 && sent < bytes_.size()) {
            const auto n = ::send(peer, bytes_.constData() + sent, std::size_t(bytes_.size() - sent), 0);
            if (n <= 0)
                break;
            sent += n;
        }
        ::close(peer);
    }

    QByteArray bytes_;
    int listener_ = -1;
    std::uint16_t port_ = 0;
    std::thread thread_;
};

void benchThroughput(std::size_t count) {
    Blaster blaster(busTraffic(count));
    transport::TcpTransport transport(
        transport::TcpSettings{"127.0.0.1", blaster.port(), transport::ReconnectTiming{}});
    bus::Bus bus(transport, busreading::BusProfile::centralStation());
    station::StationSession session(bus, sessionSettings());
    std::size_t changes = 0;
    std::size_t batches = 0;
    QObject::connect(&session, &station::StationSession::updated, [&](const station::StationUpdates& u) {
        changes += u.contacts.size() + u.speeds.size();
        ++batches;
    });
    // From connecting on: the peer sends the moment it accepts, before the event loop says "connected".
    QElapsedTimer clock;
    clock.start();
    transport.open();
    const bool all = runUntil([&] { return session.counters().frames >= count; }, 60000ms);
    const double seconds = double(clock.nsecsElapsed()) / 1e9;
    transport.close();
    const auto& c = transport.counters();
    const bool lossless = all && changes == count && c.framesIn == count && c.malformed == 0 &&
                          session.counters().undecodable == 0;
    std::printf("session over tcp: %zu frames (S88 events + speed answers) in %.3f s = %.0f frames/s, "
                "%zu batches, %zu changes reported; lost: %s  target >= 50000 frames/s: %s\n",
                std::size_t(session.counters().frames), seconds, double(session.counters().frames) / seconds,
                batches, changes, lossless ? "none" : "SOME",
                lossless && double(count) / seconds >= 50000 ? "met" : "MISSED");
}

// ---- 3. Config download --------------------------------------------------------------------------

std::string corpusLocoList() {
    std::ifstream in(std::string(STELLWERK_SHARED_DIR) +
                         "/corpus/bob123456678__TrainControl/test/lokomotive.cs2",
                     std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void benchDownload(int runs) {
    const std::string contents = corpusLocoList();
    if (contents.empty())
        return void(std::printf("config download: corpus lokomotive.cs2 missing (STELLWERK_SHARED_DIR)\n"));
    Loopback loopback(Loopback::Wire::Tcp, sim::StationLayout::fromFiles({{"lokomotive.cs2", contents}}));
    if (!loopback.connected())
        return void(std::printf("config download: could not connect\n"));
    std::vector<double> times;
    for (int run = 0; run < runs; ++run) {
        std::optional<station::DownloadResult> result;
        const auto start = Clock::now();
        auto end = start;
        loopback.session->downloads().fetch(*cs2config::ConfigRequest::forKey("loks"),
                                            [&](const station::DownloadResult& r) {
                                                end = Clock::now();
                                                result = r;
                                            });
        runUntil([&] { return result.has_value(); }, 10000ms);
        if (!result || !*result || (*result)->contents != contents)
            return void(std::printf("config download: run %d failed or differs\n", run));
        times.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    const double median = percentile(times, 0.5);
    std::printf("config download over tcp: lokomotive.cs2, %zu bytes, %d runs: median %.2f ms "
                "(min %.2f, max %.2f) = %.1f MB/s of file contents\n",
                contents.size(), runs, median, *std::min_element(times.begin(), times.end()),
                *std::max_element(times.begin(), times.end()), double(contents.size()) / median / 1000.0);
}

} // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("stellwerk.*.info=false"));
    const int roundTrips = argc > 1 ? std::atoi(argv[1]) : 2000;
    const auto frames = std::size_t(argc > 2 ? std::atoll(argv[2]) : 500000);
    benchRoundTrip(Loopback::Wire::Tcp, "tcp", roundTrips);
    benchRoundTrip(Loopback::Wire::Udp, "udp", roundTrips);
    benchThroughput(frames);
    benchDownload(20);
    return 0;
}
