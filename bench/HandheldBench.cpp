// M-CAN and the handhelds' master:
//   1. decode rate of the M-CAN codec over the chapter-11 trace (read in place from ../shared/seeds),
//      beside the CS2 codec's over CS2 traffic, and heap allocations per decoded frame (target: the same
//      order as the CS2 codec, none per frame);
//   2. the master's answer latency to a login stage on loopback: a UDP "handheld" sends stage-0 requests to
//      the master's UDP transport and times each reply (target: under 5 ms at p99).
// A plain harness printing figures. Run: build/bench/stellwerk-handheld-bench

#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "mcan/Codec.h"
#include "mcanhandhelds/HandheldMaster.h"
#include "transport/UdpTransport.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QHostAddress>
#include <QNetworkDatagram>
#include <QUdpSocket>
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::atomic<std::size_t> allocations{0};

} // namespace

void* operator new(std::size_t size) {
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}

using namespace stellwerk;

namespace {

// The chapter-11 trace of seed 002: binary ids (prio, handle bytes, cmd, node), DLC, hex data.
std::vector<can::CanFrame> chapter11() {
    std::ifstream in(std::string(STELLWERK_SHARED_DIR) + "/seeds/002_ee1b034087bd9111.txt");
    const std::regex row(
        R"(^\s*([01]{3})\s+([01]{8})\s+([01]{8})\s+([01]{3})\s+([01]{7})\s+([0-8])((?:\s+[0-9A-F]{2})*))");
    std::vector<can::CanFrame> frames;
    bool inTrace = false;
    for (std::string line; std::getline(in, line);) {
        inTrace = inTrace || line.find("wird der Telegramm Trace einer MS1") != std::string::npos;
        std::smatch m;
        if (!inTrace || !std::regex_search(line, m, row))
            continue;
        can::CanFrame frame;
        frame.id = std::uint32_t(
            std::stoul(m[1].str() + m[2].str() + m[3].str() + m[4].str() + m[5].str(), nullptr, 2));
        frame.dlc = std::uint8_t(std::stoi(m[6].str()));
        std::istringstream data(m[7].str());
        std::string byte;
        for (std::size_t i = 0; i < frame.dlc && data >> byte; ++i)
            frame.data[i] = std::uint8_t(std::stoul(byte, nullptr, 16));
        if (mcan::isMcan(frame))
            frames.push_back(frame);
    }
    return frames;
}

std::vector<can::CanFrame> cs2Traffic() {
    const char* lines[] = {"00084711 6 00 00 C0 03 01 20",       "000C4711 6 00 00 40 05 03 01",
                           "000B4711 5 00 00 C0 03 01",          "00234711 8 00 01 00 05 00 01 00 0A",
                           "00314711 8 47 43 F5 DA 01 3E 00 10", "00004711 5 00 00 00 00 01"};
    std::vector<can::CanFrame> frames;
    for (const char* line : lines)
        frames.push_back(can::parseFrame(line)->frame);
    return frames;
}

struct Rate {
    double perSecond = 0;
    double allocationsPerFrame = 0;
};

template <class Decode>
Rate decodeRate(const std::vector<can::CanFrame>& frames, Decode decode) {
    constexpr int Rounds = 200000;
    std::size_t sink = 0;
    const std::size_t before = allocations.load();
    QElapsedTimer clock;
    clock.start();
    for (int round = 0; round < Rounds; ++round)
        for (const can::CanFrame& frame : frames)
            sink += decode(frame);
    const double seconds = double(clock.nsecsElapsed()) / 1e9;
    const double count = double(Rounds) * double(frames.size());
    if (sink == 42)
        std::printf(" ");
    return {count / seconds, double(allocations.load() - before) / count};
}

void benchDecoding() {
    const std::vector<can::CanFrame> trace = chapter11();
    const Rate mcanRate =
        decodeRate(trace, [](const can::CanFrame& frame) { return mcan::decode(frame).index(); });
    const Rate cs2Rate = decodeRate(
        cs2Traffic(), [](const can::CanFrame& frame) { return cs2::decode(frame).hasValue() ? 1u : 0u; });
    std::printf("decode, one core:\n");
    std::printf("  M-CAN (the %zu M-CAN frames of the chapter-11 trace): %6.1f million frames/s, %.3f "
                "allocations per frame\n",
                trace.size(), mcanRate.perSecond / 1e6, mcanRate.allocationsPerFrame);
    std::printf("  CS2 (throttle, turnout, feedback, status, ping, stop): %6.1f million frames/s, %.3f "
                "allocations per frame\n",
                cs2Rate.perSecond / 1e6, cs2Rate.allocationsPerFrame);
}

// A handheld on the loopback network, sending stage-0 login requests to the master and timing each reply.
void benchLoginLatency() {
    QUdpSocket handheld;
    handheld.bind(QHostAddress::LocalHost, 0);
    transport::UdpSettings settings;
    settings.host = QStringLiteral("127.0.0.1");
    settings.remotePort = handheld.localPort();
    settings.localPort = 0;
    settings.localAddress = QHostAddress::LocalHost;
    transport::UdpTransport udp(settings);
    mcanhandhelds::MasterSettings quick;
    quick.loginStageTimeout = std::chrono::milliseconds(100);
    mcanhandhelds::HandheldMaster master(
        [&udp](const std::vector<can::CanFrame>& frames) { udp.sendBatch(frames); }, quick);
    QObject::connect(&udp, &transport::Transport::framesReceived, &master,
                     &mcanhandhelds::HandheldMaster::receive);
    udp.open();
    QElapsedTimer wait;
    wait.start();
    while (udp.state() != transport::Transport::State::Connected && wait.elapsed() < 3000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);

    // Each request opens a login that is never finished; the master keeps 31 at once and forgets one after
    // its stage timeout (100 ms here), so requests go in bursts of 30 with a pause between.
    constexpr int Requests = 3000;
    std::vector<double> latencies;
    for (int i = 0; i < Requests; ++i) {
        const auto bytes = mcan::encode(mcan::LoginRequest{0, std::uint8_t(i), 0}).toNetwork();
        QElapsedTimer clock;
        clock.start();
        handheld.writeDatagram(reinterpret_cast<const char*>(bytes.data()), qint64(bytes.size()),
                               QHostAddress::LocalHost, udp.boundPort());
        while (!handheld.hasPendingDatagrams() && clock.elapsed() < 1000)
            QCoreApplication::processEvents(QEventLoop::AllEvents);
        if (!handheld.hasPendingDatagrams())
            continue;
        latencies.push_back(double(clock.nsecsElapsed()) / 1e6);
        if (i % 30 == 29) { // wait until the master forgot these unfinished logins
            QElapsedTimer pause;
            pause.start();
            while (pause.elapsed() < 250)
                QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
        }
        while (handheld.hasPendingDatagrams())
            handheld.receiveDatagram();
    }
    std::sort(latencies.begin(), latencies.end());
    if (latencies.empty()) {
        std::printf("login stage 0 on loopback UDP: no answer\n");
        return;
    }
    const auto at = [&](double q) {
        return latencies[std::min(latencies.size() - 1, std::size_t(q * double(latencies.size())))];
    };
    std::printf("login stage 0 -> reply on loopback UDP (%zu of %d answered), target p99 < 5 ms:\n",
                latencies.size(), Requests);
    std::printf("  median %.3f ms, p99 %.3f ms, max %.3f ms\n", at(0.5), at(0.99), latencies.back());
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    benchDecoding();
    benchLoginLatency();
    return 0;
}
