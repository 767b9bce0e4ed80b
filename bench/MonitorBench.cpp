// The bus monitor's table under a flood, without a window:
//   1. 1,000,000 frames inserted into BusMonitorModel as a flood arrives (batches of 100 frames, one flush
//      per 5,000): frames per second and the resident memory they take (target: 1 M frames < 300 MB),
//   2. another 1,000,000 with the history full (the oldest dropped per flush): frames per second and
//      whether memory still grows,
//   3. rows formatted per second for display (the text is written lazily, only for rows shown),
//   4. the same flood with BusMonitorFilter attached (command loco.speed), as when the user filters, then
//      the whole history filtered again by Loc-ID and by text (in slices between events),
//   5. the whole panel shown (offscreen) with its table following the newest row: frames per second and
//      the longest flush, events processed after each flush as the window would.
// A plain harness printing figures. Run: build/bench/stellwerk-monitor-bench [frame count]

#include "cs2/Header.h"
#include "monitor/BusMonitorFilter.h"
#include "monitor/BusMonitorModel.h"
#include "monitor/BusMonitorPanel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <cstdio>
#include <cstdlib>
#include <malloc.h>
#include <memory>
#include <vector>

namespace {

using namespace stellwerk;
using Direction = ui::BusMonitorModel::Direction;

constexpr std::size_t BatchSize = 100;
constexpr std::size_t BatchesPerFlush = 50;

// The process's resident memory in kB, from /proc/self/status (VmRSS).
long residentKb() {
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (QByteArray line = status.readLine(); !line.isEmpty(); line = status.readLine())
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').front().toLong();
    return -1;
}

// A mix as on a busy layout: speeds for a dozen locos, S88 events, accessory switching.
std::vector<can::CanFrame> floodFrames(std::size_t count) {
    std::vector<can::CanFrame> frames(count);
    for (std::size_t i = 0; i < count; ++i) {
        can::CanFrame& frame = frames[i];
        const auto n = std::uint8_t(i);
        switch (i % 3) {
        case 0: // loco.speed
            frame.id = cs2::makeId(0, 0x04, false, 0x4711);
            frame.dlc = 6;
            frame.data = {0, 0, 0x40, std::uint8_t(n % 12), std::uint8_t(i >> 8 & 3), n};
            break;
        case 1: // feedback.s88-event
            frame.id = cs2::makeId(0, 0x11, true, 0x0300);
            frame.dlc = 8;
            frame.data = {0, 1, 0, std::uint8_t(n % 16), 0, 1, 0, 0x32};
            break;
        default: // accessory.switch
            frame.id = cs2::makeId(0, 0x0B, false, 0x4711);
            frame.dlc = 6;
            frame.data = {0, 0, 0x30, std::uint8_t(n % 64), std::uint8_t(n & 1), 1};
        }
    }
    return frames;
}

// Gives freed memory back to the system, so that the next figure starts from what is really in use.
void releaseFreed() {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
}

// Feeds `frames` into the model as a flood would: batches, and a flush now and then. Frames per second.
double feed(ui::BusMonitorModel& model, const std::vector<can::CanFrame>& frames) {
    QElapsedTimer clock;
    clock.start();
    std::size_t batches = 0;
    for (std::size_t at = 0; at < frames.size(); at += BatchSize) {
        const std::size_t size = std::min(BatchSize, frames.size() - at);
        model.addFrames({frames.data() + at, size}, Direction::Received);
        if (++batches % BatchesPerFlush == 0)
            model.flush();
    }
    model.flush();
    return double(frames.size()) / (double(clock.nsecsElapsed()) / 1e9);
}

void report(const char* what, double perSecond, long beforeKb, long afterKb) {
    std::printf("%-48s %10.0f frames/s  RSS %+7.1f MB\n", what, perSecond,
                double(afterKb - beforeKb) / 1024.0);
}

void benchModel(const std::vector<can::CanFrame>& frames) {
    const long start = residentKb();
    auto model = std::make_unique<ui::BusMonitorModel>();
    model->setHistoryLimit(int(frames.size()));
    const double fill = feed(*model, frames);
    const long filled = residentKb();
    report("1. insert until the history is full", fill, start, filled);
    std::printf("   %d rows: %.1f bytes each (target: 1 M rows < 300 MB)\n", model->rowCount(),
                double(filled - start) * 1024.0 / double(model->rowCount()));
    const double steady = feed(*model, frames);
    report("2. insert with the history full (drop oldest)", steady, filled, residentKb());

    QElapsedTimer clock;
    clock.start();
    int formatted = 0;
    for (int row = 0; row < 20000; ++row)
        for (int column = 0; column < ui::BusMonitorModel::ColumnCount; ++column)
            formatted += model->index(row, column).data().toString().size() > 0 ? 1 : 0;
    std::printf("3. rows formatted for display (all 5 columns)    %10.0f rows/s\n",
                20000.0 / (double(clock.nsecsElapsed()) / 1e9));
    (void)formatted;
}

void benchFiltered(const std::vector<can::CanFrame>& frames) {
    releaseFreed();
    const long start = residentKb();
    auto model = std::make_unique<ui::BusMonitorModel>();
    model->setHistoryLimit(int(frames.size()));
    ui::BusMonitorFilter filter;
    filter.setSourceModel(model.get());
    filter.setCommand(QStringLiteral("loco.speed"));
    const double fill = feed(*model, frames);
    report("4. insert through the command filter", fill, start, residentKb());
    std::printf("   %d of %d rows pass the filter\n", filter.rowCount(), model->rowCount());
    const auto scan = [&](const char* what) {
        QElapsedTimer clock;
        QElapsedTimer turn;
        clock.start();
        qint64 longestTurnNs = 0;
        while (filter.isScanning()) {
            turn.start();
            QCoreApplication::processEvents();
            longestTurnNs = std::max(longestTurnNs, turn.nsecsElapsed());
        }
        std::printf("   %-24s over %d rows: %6.0f ms in all, longest turn %5.1f ms; %d rows pass\n", what,
                    model->rowCount(), double(clock.nsecsElapsed()) / 1e6, double(longestTurnNs) / 1e6,
                    filter.rowCount());
    };
    filter.setLocId(0x4003);
    scan("Loc-ID added");
    filter.setFilters(QString(), std::nullopt, QStringLiteral("contact=5"));
    scan("text alone");
}

void benchPanel(const std::vector<can::CanFrame>& frames) {
    releaseFreed();
    const long start = residentKb();
    ui::BusMonitorPanel panel;
    panel.resize(1200, 700);
    panel.show();
    QApplication::processEvents();
    ui::BusMonitorModel& model = *panel.model();
    model.setHistoryLimit(int(frames.size()));
    QElapsedTimer clock;
    QElapsedTimer flushClock;
    clock.start();
    qint64 longestFlushNs = 0;
    for (std::size_t at = 0; at < frames.size(); at += BatchSize * BatchesPerFlush) {
        for (std::size_t batch = 0; batch < BatchesPerFlush; ++batch) {
            const std::size_t from = std::min(frames.size(), at + batch * BatchSize);
            model.addFrames({frames.data() + from, std::min(BatchSize, frames.size() - from)},
                            Direction::Received);
        }
        flushClock.start();
        model.flush();
        QApplication::processEvents(); // layout and paint, as the window's event loop would
        longestFlushNs = std::max(longestFlushNs, flushClock.nsecsElapsed());
    }
    report("5. the panel shown, following the newest row",
           double(frames.size()) / (double(clock.nsecsElapsed()) / 1e9), start, residentKb());
    std::fflush(stdout);
    std::printf("   longest flush + repaint of %zu frames: %.1f ms\n", BatchSize * BatchesPerFlush,
                double(longestFlushNs) / 1e6);
}

} // namespace

int main(int argc, char* argv[]) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const auto count = std::size_t(argc > 1 ? std::atoll(argv[1]) : 1000000);
    const std::vector<can::CanFrame> frames = floodFrames(count);
    benchModel(frames);
    benchFiltered(frames);
    benchPanel(frames);
    return 0;
}
