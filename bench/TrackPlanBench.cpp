// The track plan view, offscreen:
//   1. drawing a page of 2,000 elements (target: under 16 ms per full repaint),
//   2. 2,000 S88 events per second from the simulated CS2 through the Railway while the plan is shown:
//      how late the event loop serves a 5 ms timer (the UI's responsiveness), and how many events arrived.
// A plain harness printing figures. Run: QT_QPA_PLATFORM=offscreen build/bench/stellwerk-trackplan-bench

#include "RailwayBinding.h"
#include "TrackPageView.h"
#include "TrackPlanPanel.h"
#include "TrackTileLook.h"
#include "connection/StationConnection.h"
#include "cs2config/TrackElementType.h"
#include "model/Railway.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QImage>
#include <QPainter>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <vector>

using namespace stellwerk;

namespace {

// A 50 x 40 page with 2,000 tiles cycling through every element type and rotation.
model::TrackLayout bigLayout() {
    station::DownloadedPage page;
    page.name = "bench";
    const auto types = cs2config::trackElementTypes();
    for (int i = 0; i < 2000; ++i) {
        cs2config::TrackElement element;
        element.position = {0, std::uint8_t(i % 50), std::uint8_t(i / 50)};
        element.type = std::string(types[std::size_t(i) % types.size()].name);
        element.rotation = (i / int(types.size())) % 4;
        element.text = "Gleis";
        page.page.elements.push_back(element);
    }
    return model::TrackLayout({page});
}

void benchDrawing() {
    const model::TrackLayout layout = bigLayout();
    const model::LayoutPage& page = layout.pages()[0];
    ui::TrackPageView view(
        page,
        [&page](int tile) {
            const model::LayoutTile& t = page.tiles[std::size_t(tile)];
            return ui::TrackTileLook{t.type, t.category, t.rotation, tile % 2, tile % 3 == 0, false, t.text};
        },
        [](int) { return QString(); });
    view.setTileSize(24);
    view.resize(view.sizeHint());
    QImage image(view.size(), QImage::Format_ARGB32_Premultiplied);
    std::vector<double> times;
    for (int run = 0; run < 30; ++run) {
        QElapsedTimer clock;
        clock.start();
        view.render(&image);
        times.push_back(double(clock.nsecsElapsed()) / 1e6);
    }
    std::sort(times.begin(), times.end());
    std::printf("draw a page of 2000 elements (%dx%d px): median %.2f ms, worst %.2f ms (target < 16 ms)\n",
                view.width(), view.height(), times[times.size() / 2], times.back());
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
    ui::RailwayBinding railways(connection);
    ui::TrackPlanPanel panel;
    QObject::connect(&railways, &ui::RailwayBinding::railwayChanged, &panel, &ui::TrackPlanPanel::setRailway);
    panel.resize(1200, 800);
    panel.show();
    connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(server.tcpPort()));
    QElapsedTimer wait;
    wait.start();
    while (connection.state() != connection::StationConnection::State::Ready && wait.elapsed() < 15000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    if (!railways.railway()) {
        std::printf("contacts: the simulated station did not get ready\n");
        return;
    }
    int changes = 0;
    QObject::connect(railways.railway(), &model::Railway::contactsChanged,
                     [&](const QList<quint32>& keys) { changes += int(keys.size()); });
    // 2 events every millisecond on the demo's contacts 1..9, toggling.
    int sent = 0;
    QTimer feed;
    feed.setTimerType(Qt::PreciseTimer);
    QObject::connect(&feed, &QTimer::timeout, [&] {
        for (int i = 0; i < 2; ++i, ++sent)
            station.setContact(0, std::uint16_t(1 + sent % 9), (sent / 9) % 2 == 0);
    });
    std::vector<double> lateness;
    QElapsedTimer clock;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    qint64 expected = 5;
    QObject::connect(&probe, &QTimer::timeout, [&] {
        lateness.push_back(std::max<double>(0, double(clock.elapsed() - expected)));
        expected = clock.elapsed() + 5;
    });
    clock.start();
    feed.start(1);
    probe.start(5);
    while (clock.elapsed() < 5000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    feed.stop();
    probe.stop();
    std::sort(lateness.begin(), lateness.end());
    const double seconds = double(clock.elapsed()) / 1000.0;
    std::printf(
        "S88 events with the plan shown: %.0f sent/s, %.0f contact changes/s arrived; 5 ms timer late by "
        "median %.1f ms, p99 %.1f ms, worst %.1f ms\n",
        sent / seconds, changes / seconds, lateness[lateness.size() / 2],
        lateness[std::size_t(double(lateness.size() - 1) * 0.99)], lateness.back());
}

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    benchDrawing();
    benchContacts();
    return 0;
}
