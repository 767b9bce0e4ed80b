// The track plan view, offscreen:
//   1. drawing a page of 2,000 elements at the default zoom (target: under 16 ms per full repaint),
//   2. the 2,000-tile station of the track graph's benchmark with its blocks shown (outlines, names,
//      problem markers) and without: a full repaint must not get noticeably slower,
//   3. 2,000 S88 events per second (batches of 20 every 10 ms) from the simulated CS2 over loopback TCP
//      through the session and the Railway while the plan is shown: how many events arrived and how
//      late the event loop serves a 5 ms timer (the UI's responsiveness).
// A plain harness printing figures. Run: QT_QPA_PLATFORM=offscreen build/bench/stellwerk-trackplan-bench

#include "BenchmarkPage.h"
#include "binding/RailwayBinding.h"
#include "connection/StationConnection.h"
#include "cs2config/TrackElementType.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"
#include "station/StationSession.h"
#include "station/StationUpdates.h"
#include "trackgraph/TrackGraph.h"
#include "trackplan/BlockOutlines.h"
#include "trackplan/PaintBands.h"
#include "trackplan/PlanGraph.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"
#include "trackplan/TrackTileLook.h"
#include "trackplan/TrackTilePainter.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QImage>
#include <QPainter>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace stellwerk;

namespace {

// The benchmarks' 2,000-tile page (BenchmarkPage.h) as the plan's model.
model::TrackLayout bigLayout(bool ownNames) {
    station::DownloadedPage page;
    page.name = "bench";
    page.page.elements = bench::benchmarkPage(ownNames);
    return model::TrackLayout({page});
}

struct Figures {
    double median = 0;
    double worst = 0;
};

template <typename Draw>
Figures timed(int runs, Draw draw) {
    std::vector<double> times;
    for (int run = 0; run < runs; ++run) {
        QElapsedTimer clock;
        clock.start();
        draw();
        times.push_back(double(clock.nsecsElapsed()) / 1e6);
    }
    std::sort(times.begin(), times.end());
    return {times[times.size() / 2], times.back()};
}

// A page's first paint on fresh views: in bands on all cores, in one band (as before PaintBands), and in
// memory nothing touched before.
void benchFirstPaints(const std::shared_ptr<const model::LayoutPage>& shared,
                      const ui::TrackPageView::LookOf& lookOf, QImage& image) {
    // Each first paint on a view of its own, so that nothing is drawn yet (the memory the view before freed
    // is drawn into again, as when the program shows another page).
    const auto freshPaint = [&] {
        ui::TrackPageView fresh(shared, lookOf, [](int) { return QString(); });
        fresh.resize(fresh.sizeHint());
        fresh.render(&image);
    };
    const Figures first = timed(7, freshPaint);
    std::printf("  first paint (draws pictures):   median %6.2f ms, worst %6.2f ms\n", first.median,
                first.worst);
    ui::PaintBands::setEnabled(false);
    const Figures oneBand = timed(7, freshPaint);
    ui::PaintBands::setEnabled(true);
    std::printf("  first paint in one band:        median %6.2f ms, worst %6.2f ms\n", oneBand.median,
                oneBand.worst);
    // The same with every view kept: nothing freed before is drawn into again, as on a program's very first
    // page. On a virtual machine each first touch of a memory page costs (12 us per page seen here).
    std::vector<std::unique_ptr<ui::TrackPageView>> kept;
    for (int i = 0; i < 7; ++i) {
        kept.push_back(std::make_unique<ui::TrackPageView>(shared, lookOf, [](int) { return QString(); }));
        kept.back()->resize(kept.back()->sizeHint());
    }
    std::size_t next = 0;
    const Figures cold = timed(7, [&] { kept[next++]->render(&image); });
    kept.clear();
    std::printf("  first paint in untouched memory: median %6.2f ms, worst %6.2f ms\n", cold.median,
                cold.worst);
}

void benchDrawing(bool ownNames) {
    const model::TrackLayout layout = bigLayout(ownNames);
    const auto shared = std::make_shared<const model::LayoutPage>(layout.pages()[0]);
    const model::LayoutPage& page = *shared;
    const auto lookOf = [&page](int tile) {
        const model::LayoutTile& t = page.tiles[std::size_t(tile)];
        return ui::TrackTileLook{t.type, t.category, t.rotation, tile % 2, tile % 3 == 0, false, t.text};
    };
    ui::TrackPageView view(shared, lookOf, [](int) { return QString(); });
    view.resize(view.sizeHint()); // the default zoom: 40 px per tile
    QImage image(view.size(), QImage::Format_ARGB32_Premultiplied);
    std::printf("draw a page of 2000 elements (%s) at %d px per tile (%dx%d px), target < 16 ms:\n",
                ownNames ? "2000 different names" : "all named Gleis", view.tileSize(), view.width(),
                view.height());

    // Every tile stroked as vector paths, as the view did before it kept pictures of its tiles.
    const ui::TrackColors colors = ui::TrackColors::from(view.palette());
    const Figures direct = timed(5, [&] {
        QPainter painter(&image);
        painter.setFont(view.font());
        painter.fillRect(image.rect(), colors.background);
        for (int i = 0; i < int(page.tiles.size()); ++i)
            ui::TrackTilePainter::paint(painter, view.tileRect(i), lookOf(i), colors);
    });
    std::printf("  every tile stroked:             median %6.2f ms, worst %6.2f ms\n", direct.median,
                direct.worst);
    benchFirstPaints(shared, lookOf, image);
    view.render(&image);
    const Figures repaint = timed(30, [&] { view.render(&image); });
    std::printf("  full repaint:                   median %6.2f ms, worst %6.2f ms\n", repaint.median,
                repaint.worst);
    ui::PaintBands::setEnabled(false);
    const Figures oneBand = timed(30, [&] { view.render(&image); });
    ui::PaintBands::setEnabled(true);
    std::printf("  full repaint in one band:       median %6.2f ms, worst %6.2f ms\n", oneBand.median,
                oneBand.worst);
    int step = 0; // zooming in and out by 4 px, each size new to the view
    const Figures zoomed = timed(7, [&] {
        ++step;
        view.setTileSize(40 + (step % 2 ? 4 * step : -step));
        view.render(&image);
    });
    std::printf("  first repaint after zooming:    median %6.2f ms, worst %6.2f ms\n", zoomed.median,
                zoomed.worst);
}

// The station page of 2,000 tiles and about 200 blocks: a full repaint without and with the blocks shown,
// and the first repaint after the blocks were given (laying out their bands and names).
void benchBlocks() {
    station::DownloadedPage downloaded;
    downloaded.name = "station";
    downloaded.page.elements = bench::stationPage();
    const model::TrackLayout layout({downloaded});
    trackgraph::GraphSource source;
    source.pages.push_back({0, "station", &downloaded.page.elements});
    const std::shared_ptr<const ui::PlanGraph> graph = ui::PlanGraph::of(
        std::make_shared<const trackgraph::TrackGraph>(trackgraph::TrackGraph::derive(source)), layout);
    const auto shared = std::make_shared<const model::LayoutPage>(layout.pages()[0]);
    const auto lookOf = [&page = *shared](int tile) {
        const model::LayoutTile& t = page.tiles[std::size_t(tile)];
        return ui::TrackTileLook{t.type, t.category, t.rotation, 1, false, false, t.text};
    };
    ui::TrackPageView view(shared, lookOf, [](int) { return QString(); });
    view.resize(view.sizeHint());
    QImage image(view.size(), QImage::Format_ARGB32_Premultiplied);
    std::printf("the 2000-tile station with %zu blocks and %zu problems at %d px per tile (%dx%d px):\n",
                graph->graph().blocks().size(), graph->graph().problems().size(), view.tileSize(),
                view.width(), view.height());
    view.render(&image);
    const Figures plain = timed(30, [&] { view.render(&image); });
    std::printf("  full repaint, blocks not shown:  median %6.2f ms, worst %6.2f ms\n", plain.median,
                plain.worst);
    const Figures laidOut = timed(7, [&] {
        view.setBlocks(ui::BlockOutlines::ofPage(*graph, 0));
        view.setProblemTiles(graph->problemTilesOf(0));
        view.render(&image);
    });
    std::printf("  first repaint with the blocks:   median %6.2f ms, worst %6.2f ms\n", laidOut.median,
                laidOut.worst);
    const Figures shown = timed(30, [&] { view.render(&image); });
    std::printf("  full repaint, blocks shown:      median %6.2f ms, worst %6.2f ms\n", shown.median,
                shown.worst);
}

// Every 10 ms a batch of 20 events, as a busy S88 bus delivers them: 2,000 events per second on the demo's
// contacts 1..9, each event a real change; for 5 s.
constexpr int BatchMs = 10;
constexpr int BatchSize = 20;
constexpr qint64 RunMs = 5000;

// Waits until the connection is ready and the binding has a railway (at most 15 s).
bool waitForRailway(const connection::StationConnection& connection,
                    const binding::RailwayBinding& railways) {
    QElapsedTimer wait;
    wait.start();
    while (connection.state() != connection::StationConnection::State::Ready && wait.elapsed() < 15000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    return railways.railway() != nullptr;
}

// What a contact run sent, for how long, and how late a 5 ms timer fired meanwhile (sorted).
struct ContactRun {
    int sent = 0;
    double seconds = 0;
    std::vector<double> lateness;
};

// Feeds the station's contacts for RunMs while a 5 ms timer measures the event loop's latency.
ContactRun feedContacts(sim::SimulatedStation& station) {
    ContactRun run;
    QElapsedTimer clock;
    QTimer feed;
    feed.setTimerType(Qt::PreciseTimer);
    QObject::connect(&feed, &QTimer::timeout, [&] {
        const qint64 due = clock.elapsed() * BatchSize / BatchMs; // catch up when the timer was late
        for (; run.sent < due; ++run.sent)
            station.setContact(0, std::uint16_t(1 + run.sent % 9), (run.sent / 9) % 2 == 0);
    });
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    qint64 expectedNs = 5000000;
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        run.lateness.push_back(std::max<double>(0, double(now - expectedNs) / 1e6));
        expectedNs = now + 5000000;
    });
    clock.start();
    feed.start(BatchMs);
    probe.start(5);
    while (clock.elapsed() < RunMs)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    feed.stop();
    probe.stop();
    run.seconds = double(clock.elapsed()) / 1000.0;
    std::sort(run.lateness.begin(), run.lateness.end());
    return run;
}

void printContactFigures(const ContactRun& run, int delivered, int tileUpdates) {
    const double seconds = run.seconds;
    const std::vector<double>& lateness = run.lateness;
    std::printf("S88 events with the plan shown, batches of %d every %d ms for %.1f s:\n", BatchSize, BatchMs,
                seconds);
    std::printf("  sent %.0f events/s, delivered %.0f events/s (%d of %d), %.0f tile updates/s\n",
                run.sent / seconds, delivered / seconds, delivered, run.sent, tileUpdates / seconds);
    std::printf("  event loop latency (5 ms timer late by): median %.2f ms, p99 %.2f ms, max %.2f ms\n",
                lateness[lateness.size() / 2], lateness[std::size_t(double(lateness.size() - 1) * 0.99)],
                lateness.back());
}

void benchContacts() {
    sim::SimulatedStation station(sim::StationLayout::demo());
    sim::StationServerSettings settings;
    settings.listenAddress = QHostAddress(QHostAddress::LocalHost);
    settings.udp = false;
    settings.tcpPort = 0;
    sim::StationServer server(station, settings);
    server.listen();
    connection::StationConnection connection;
    model::LayoutInUse layout;
    binding::RailwayBinding railways(connection, &layout);
    ui::TrackPlanPanel panel;
    panel.setLayoutInUse(&layout);
    QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &panel,
                     &ui::TrackPlanPanel::setRailway);
    panel.resize(1200, 800);
    panel.show();
    connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(server.tcpPort()));
    if (!waitForRailway(connection, railways)) {
        std::printf("contacts: the simulated station did not get ready\n");
        return;
    }
    // Count what really arrives: every contact event the session decodes, and the plan's tile updates.
    int delivered = 0;
    int tileUpdates = 0;
    QObject::connect(
        connection.session(), &station::StationSession::updated,
        [&](const station::StationUpdates& updates) { delivered += int(updates.contacts.size()); });
    QObject::connect(railways.railway(), &model::Railway::tilesChanged,
                     [&](const QList<model::TileRef>& tiles) { tileUpdates += int(tiles.size()); });
    const ContactRun run = feedContacts(station);
    QElapsedTimer drain; // the events still on their way
    drain.start();
    while (delivered < run.sent && drain.elapsed() < 2000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    printContactFigures(run, delivered, tileUpdates);
}

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    benchDrawing(false);
    benchDrawing(true);
    benchBlocks();
    benchContacts();
    return 0;
}
