// The bus monitor with more than one bus: each row knows its bus and protocol, the bus column shows
// only when there is more than one, the protocol filter picks one protocol, and a recording keeps the
// bus of each frame (can0, can1, ...) for its replay.

#include "EmbeddedStationSupport.h"
#include "ModuleBusPeer.h"
#include "can/FrameText.h"
#include "monitor/BusMonitorFilter.h"
#include "monitor/BusMonitorModel.h"
#include "monitor/BusMonitorPanel.h"
#include "monitor/BusMonitorReplay.h"
#include "shell/Translations.h"
#include "support/MonitorTestSupport.h"

#include <QFile>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using Direction = BusMonitorModel::Direction;
using test::cell;
using test::frame;
using test::systemStop;

namespace {

std::vector<MonitoredBus> stationAndModules() {
    return {{QStringLiteral("station"), busreading::BusProfile::centralStation()},
            {QStringLiteral("127.0.0.1:7000"), busreading::BusProfile{}}};
}

// The embedded station and a module bus, with the monitor watching both.
struct TwoBusesOnScreen {
    TwoBusesOnScreen() : connection(support::withEmbeddedStation()) {
        translations.select(Language::English);
        panel.setBuses(&connection.buses());
    }
    bool start() {
        if (!modules.listen())
            return false;
        connection.connectTo(QString(), {modules.url()});
        return QTest::qWaitFor([&] { return connection.buses().isBusConnected(1) && modules.hasClient(); },
                               10000);
    }
    Translations translations;
    support::ModuleBusPeer modules;
    connection::StationConnection connection;
    BusMonitorPanel panel;
};

} // namespace

TEST(BusMonitorModel, ARowIsReadWithTheProtocolsOfItsBus) {
    BusMonitorModel model;
    model.setBuses(stationAndModules());
    const std::vector frames{systemStop()};
    model.addFrames(frames, Direction::Received, QDateTime::currentDateTime(), 0);
    model.addFrames(frames, Direction::Received, QDateTime::currentDateTime(), 1);
    model.flush();
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.busAt(0), 0);
    EXPECT_EQ(model.busAt(1), 1);
    EXPECT_EQ(cell(model, 0, BusMonitorModel::BusColumn), QStringLiteral("station"));
    EXPECT_EQ(cell(model, 1, BusMonitorModel::BusColumn), QStringLiteral("127.0.0.1:7000"));
    EXPECT_EQ(model.protocolAt(0), busreading::Protocol::Cs2);
    EXPECT_EQ(model.protocolAt(1), busreading::Protocol::Foreign)
        << "the same bytes on a module bus are no CS2";
    EXPECT_EQ(cell(model, 0, 0, BusMonitorModel::ProtocolRole), QStringLiteral("cs2"));
    EXPECT_EQ(cell(model, 1, 0, BusMonitorModel::ProtocolRole), QStringLiteral("foreign"));
    EXPECT_EQ(cell(model, 0, BusMonitorModel::MessageColumn), QStringLiteral("system.stop"));
    EXPECT_NE(cell(model, 1, BusMonitorModel::MessageColumn), QStringLiteral("system.stop"));
}

TEST(BusMonitorModel, ABusNobodyNamedIsCalledByItsNumber) {
    BusMonitorModel model;
    QSignalSpy counted(&model, &BusMonitorModel::busCountChanged);
    const std::vector frames{systemStop()};
    model.addFrames(frames, Direction::Received, QDateTime::currentDateTime(), 0);
    EXPECT_EQ(model.busCount(), 1);
    EXPECT_EQ(counted.count(), 0);
    model.addFrames(frames, Direction::Received, QDateTime::currentDateTime(), 3);
    model.flush();
    EXPECT_EQ(model.busCount(), 4);
    EXPECT_EQ(counted.count(), 1);
    EXPECT_EQ(cell(model, 1, BusMonitorModel::BusColumn), QStringLiteral("can3"));
    EXPECT_EQ(model.protocolAt(0), busreading::Protocol::Cs2) << "bus 0 is the station's";
    EXPECT_EQ(model.protocolAt(1), busreading::Protocol::Foreign);
    model.clear();
    EXPECT_EQ(model.busCount(), 1);
    EXPECT_EQ(counted.count(), 2);
}

TEST(BusMonitorFilter, TheProtocolFilterKeepsOnlyThatProtocolsRows) {
    BusMonitorModel model;
    model.setBuses(stationAndModules());
    BusMonitorFilter filter;
    filter.setSourceModel(&model);
    const std::vector frames{systemStop()};
    for (int bus : {0, 1, 0})
        model.addFrames(frames, Direction::Received, QDateTime::currentDateTime(), bus);
    model.flush();
    filter.setProtocol(busreading::Protocol::Foreign);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !filter.isScanning(); }));
    ASSERT_EQ(filter.rowCount(), 1);
    EXPECT_EQ(model.busAt(filter.mapToSource(filter.index(0, 0)).row()), 1);
    filter.setProtocol(busreading::Protocol::Cs2);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !filter.isScanning(); }));
    EXPECT_EQ(filter.rowCount(), 2);
    filter.setProtocol(std::nullopt);
    EXPECT_EQ(filter.rowCount(), 3);
}

TEST(BusMonitorPanel, TheBusColumnShowsOnlyWithMoreThanOneBus) {
    connection::StationConnection station{support::withEmbeddedStation()};
    BusMonitorPanel panel;
    panel.setBuses(&station.buses());
    station.connectTo(QString());
    EXPECT_TRUE(panel.table()->isColumnHidden(BusMonitorModel::BusColumn));

    support::ModuleBusPeer modules;
    ASSERT_TRUE(modules.listen());
    station.connectTo(QString(), {modules.url()});
    EXPECT_FALSE(panel.table()->isColumnHidden(BusMonitorModel::BusColumn));
    const QString place = QStringLiteral("127.0.0.1:%1").arg(modules.port());
    EXPECT_GT(panel.table()->columnWidth(BusMonitorModel::BusColumn),
              panel.table()->fontMetrics().horizontalAdvance(place))
        << "the further bus's place is not cut";
    station.connectTo(QString());
    panel.model()->clear();
    EXPECT_TRUE(panel.table()->isColumnHidden(BusMonitorModel::BusColumn));
}

// A module frame on the live view: shown on its bus as foreign, found by the protocol filter, and not
// among the CS2 rows.
TEST(BusMonitorPanel, ShowsModuleFramesOnTheirBusAndFiltersByProtocol) {
    TwoBusesOnScreen screen;
    ASSERT_TRUE(screen.start());
    ASSERT_TRUE(screen.panel.setProtocolFilter(QStringLiteral("foreign")));
    screen.modules.send({systemStop()});
    const QAbstractItemModel& shown = *screen.panel.table()->model();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.rowCount() == 1; }, 5000));
    EXPECT_EQ(cell(shown, 0, BusMonitorModel::BusColumn),
              QStringLiteral("127.0.0.1:%1").arg(screen.modules.port()));
    EXPECT_EQ(cell(shown, 0, 0, BusMonitorModel::ProtocolRole), QStringLiteral("foreign"));
    EXPECT_FALSE(screen.panel.table()->isColumnHidden(BusMonitorModel::BusColumn));

    ASSERT_TRUE(screen.panel.setProtocolFilter(QStringLiteral("cs2")));
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.rowCount() > 0; }, 5000)) << "the station's pings";
    for (int row = 0; row < shown.rowCount(); ++row)
        EXPECT_EQ(cell(shown, row, BusMonitorModel::BusColumn), QStringLiteral("station"));
    EXPECT_FALSE(screen.panel.setProtocolFilter(QStringLiteral("openrailcan"))) << "no codec for it yet";
}

// Recorded with two buses, a module frame is written on can1; played back, it is on bus 1 again.
TEST(BusMonitorPanel, ARecordingKeepsEachFramesBus) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("two-buses.log"));
    TwoBusesOnScreen screen;
    ASSERT_TRUE(screen.start());
    ASSERT_TRUE(screen.panel.startRecording(path).isEmpty());
    const std::uint64_t stationFrames = screen.connection.buses().busFrames(0, busreading::Protocol::Cs2);
    screen.modules.send({systemStop()});
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return screen.connection.buses().busFrames(1, busreading::Protocol::Foreign) == 1 &&
                   screen.connection.buses().busFrames(0, busreading::Protocol::Cs2) > stationFrames;
        },
        10000));
    screen.panel.stopRecording();
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray log = file.readAll();
    EXPECT_TRUE(log.contains(") can1 00004711#0000000000 R\n")) << log.toStdString();
    EXPECT_TRUE(log.contains(") can0 ")) << "the station's frames on can0";

    screen.connection.disconnectFromStation();
    ASSERT_TRUE(screen.panel.openLog(path).isEmpty());
    screen.panel.setReplaySpeed(BusMonitorReplay::AsFastAsPossible);
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return screen.panel.replay()->state() == BusMonitorReplay::State::Finished; }));
    screen.panel.model()->flush();
    const BusMonitorModel& rows = *screen.panel.model();
    int onCan1 = 0;
    for (int row = 0; row < rows.rowCount(); ++row)
        if (rows.busAt(row) == 1) {
            ++onCan1;
            EXPECT_EQ(cell(rows, row, BusMonitorModel::BusColumn), QStringLiteral("can1"));
            EXPECT_EQ(rows.protocolAt(row), busreading::Protocol::Foreign);
        }
    EXPECT_EQ(onCan1, 1);
    EXPECT_FALSE(screen.panel.table()->isColumnHidden(BusMonitorModel::BusColumn));
}

// "← empfangen" is longer than "← received": the Direction column grows with the language in use.
TEST(BusMonitorPanel, TheDirectionColumnFitsItsTextInEveryLanguage) {
    Translations translations;
    BusMonitorPanel panel;
    for (const Language language : {Language::English, Language::German}) {
        ASSERT_TRUE(translations.select(language));
        QCoreApplication::processEvents();
        const QFontMetrics metrics = panel.table()->fontMetrics();
        const int width = panel.table()->columnWidth(BusMonitorModel::DirectionColumn);
        const int margins = 2 * metrics.horizontalAdvance(QLatin1Char('0')); // the cell's padding, not elided
        for (const Direction direction : {Direction::Received, Direction::Sent})
            EXPECT_GE(width, metrics.horizontalAdvance(BusMonitorModel::directionText(direction)) + margins)
                << BusMonitorModel::directionText(direction).toStdString();
    }
    translations.select(Language::English);
}

// docs/screenshots/bus-monitor-two-buses.png and -de.png: the station and a module bus, with the Bus column.
TEST(BusMonitorPanel, SavesTheTwoBusScreenshotsWhenAsked) {
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    if (folder.isEmpty())
        GTEST_SKIP() << "set STELLWERK_SCREENSHOT_DIR to save the screenshots";
    for (const auto& [language, name] : {std::pair{Language::English, "bus-monitor-two-buses.png"},
                                         std::pair{Language::German, "bus-monitor-two-buses-de.png"}}) {
        TwoBusesOnScreen screen;
        ASSERT_TRUE(screen.translations.select(language));
        ASSERT_TRUE(screen.start());
        ASSERT_TRUE(QTest::qWaitFor(
            [&] { return screen.connection.state() == connection::StationConnection::State::Ready; }, 10000));
        screen.modules.send(
            {frame("00004711 5 00 00 00 00 00"), frame("1C400300 4 00 01 00 01"), frame("1C410300 2 01 00")});
        ASSERT_TRUE(QTest::qWaitFor(
            [&] { return screen.connection.buses().busFrames(1, busreading::Protocol::Foreign) == 3; }));
        screen.panel.resize(1300, 420);
        screen.panel.show();
        QTest::qWait(300);
        EXPECT_TRUE(screen.panel.grab().save(folder + QLatin1Char('/') + QLatin1String(name)));
    }
}
