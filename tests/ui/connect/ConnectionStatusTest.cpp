#include "connect/ConnectionStatus.h"

#include "EmbeddedStationSupport.h"
#include "shell/MainWindow.h"
#include "shell/PassingMessage.h"
#include "shell/Translations.h"
#include "support/StationTestSupport.h"

#include <QCoreApplication>
#include <QEvent>
#include <QLabel>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;
using test::waitForState;

namespace {

// The status line following a connection, in English unless a test switches to German.
class ConnectionStatusTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        status.setConnection(&station);
    }
    void TearDown() override { translations.select(Language::English); }

    // Switches the language the way View → Language does and lets the widget hear of it.
    void choose(Language language) {
        ASSERT_TRUE(translations.select(language));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
    QString shown() const { return status.findChild<QLabel*>(QStringLiteral("stationStatus"))->text(); }

    Translations translations;
    connection::StationConnection station{support::withEmbeddedStation()};
    ConnectionStatus status;
};

} // namespace

TEST(ConnectionStatusAlone, WithoutAConnectionSaysNoStationConnected) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    ConnectionStatus status;
    EXPECT_EQ(status.text(), QStringLiteral("No station connected"));
}

TEST_F(ConnectionStatusTest, DisconnectedSaysNoStationConnected) {
    EXPECT_EQ(shown(), QStringLiteral("No station connected"));
    choose(Language::German);
    EXPECT_EQ(shown(), QStringLiteral("Keine Zentrale verbunden"));
}

TEST_F(ConnectionStatusTest, ConnectingNamesTheStation) {
    const std::uint16_t port = test::closedTcpPort();
    station.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(port));
    ASSERT_EQ(station.state(), State::Connecting);
    EXPECT_EQ(shown(), QStringLiteral("CS2 at 127.0.0.1:%1 (TCP) — connecting").arg(port));
    choose(Language::German);
    EXPECT_EQ(shown(), QStringLiteral("CS2 unter 127.0.0.1:%1 (TCP) — Verbindung wird aufgebaut").arg(port));
}

TEST_F(ConnectionStatusTest, LoadingShowsStepFileAndPercentage) {
    QStringList texts; // what the line said at each progress report
    QObject::connect(&station, &connection::StationConnection::progressChanged, [&] { texts << shown(); });
    station.connectToSimulator();
    ASSERT_TRUE(waitForState(station, State::Ready));
    EXPECT_TRUE(
        texts.contains(QStringLiteral("Simulated CS2 (demo layout) — loading configuration 1/5: listing the "
                                      "devices")))
        << texts.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(texts.contains(
        QStringLiteral("Simulated CS2 (demo layout) — loading configuration 4/5: lokomotive.cs2 100 %")))
        << texts.join(QLatin1Char('\n')).toStdString();
}

TEST_F(ConnectionStatusTest, LoadingInGerman) {
    choose(Language::German);
    QStringList texts;
    QObject::connect(&station, &connection::StationConnection::progressChanged, [&] { texts << shown(); });
    station.connectToSimulator();
    ASSERT_TRUE(waitForState(station, State::Ready));
    EXPECT_TRUE(texts.contains(QStringLiteral(
        "Simulierte CS2 (Demo-Anlage) — Konfiguration wird geladen 4/5: lokomotive.cs2 100 %")))
        << texts.join(QLatin1Char('\n')).toStdString();
}

TEST_F(ConnectionStatusTest, ReadyCountsLocomotivesAccessoriesAndPages) {
    station.connectToSimulator();
    ASSERT_TRUE(waitForState(station, State::Ready));
    EXPECT_EQ(shown(),
              QStringLiteral("Simulated CS2 (demo layout) — ready: 12 locomotives, 12 accessories, 3 pages"));
    choose(Language::German);
    EXPECT_EQ(shown(),
              QStringLiteral("Simulierte CS2 (Demo-Anlage) — bereit: 12 Loks, 12 Magnetartikel, 3 Seiten"));
}

TEST_F(ConnectionStatusTest, SilentWhenTheStationGoesAway) {
    test::TestStation server;
    ASSERT_TRUE(server.start());
    const std::uint16_t port = server.port();
    station.connectTo(server.url());
    ASSERT_TRUE(waitForState(station, State::Ready));
    server.stop();
    ASSERT_TRUE(waitForState(station, State::Silent, 5000));
    EXPECT_EQ(shown(), QStringLiteral("CS2 at 127.0.0.1:%1 (TCP) — station silent").arg(port));
    choose(Language::German);
    EXPECT_EQ(shown(), QStringLiteral("CS2 unter 127.0.0.1:%1 (TCP) — Zentrale antwortet nicht").arg(port));
}

TEST_F(ConnectionStatusTest, FailedGivesTheReason) {
    station.connectTo(QStringLiteral("http://cs2"));
    ASSERT_EQ(station.state(), State::Failed);
    ASSERT_FALSE(station.failureReason().isEmpty());
    EXPECT_EQ(shown(), QStringLiteral("Station \"http://cs2\" — failed: %1").arg(station.failureReason()));
    choose(Language::German);
    EXPECT_EQ(shown(),
              QStringLiteral("Zentrale „http://cs2“ — fehlgeschlagen: %1").arg(station.failureReason()));
}

TEST_F(ConnectionStatusTest, LampIsShownBesideTheText) {
    const auto* lamp = status.findChild<QLabel*>(QStringLiteral("stationLamp"));
    ASSERT_NE(lamp, nullptr);
    EXPECT_FALSE(lamp->pixmap().isNull());
}

TEST_F(ConnectionStatusTest, MainWindowShowsWhatToTryBesideAFailureInsteadOfRepeatingIt) {
    MainWindow window(translations);
    window.setConnection(&station);
    QSignalSpy problems(&station, &connection::StationConnection::problem);
    station.connectTo(QStringLiteral("http://cs2"));
    ASSERT_EQ(problems.count(), 1);
    EXPECT_EQ(
        window.passingMessage()->text(),
        QStringLiteral("Try: correct the address in Station → Connect…, for example udp://192.168.2.5."));
}

TEST_F(ConnectionStatusTest, MainWindowShowsProblemsWhileConnectingWithWhatToTry) {
    MainWindow window(translations);
    window.setConnection(&station);
    QSignalSpy problems(&station, &connection::StationConnection::problem);
    station.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(test::closedTcpPort()));
    ASSERT_TRUE(problems.wait(test::ReadyMs));
    const QString shown = window.passingMessage()->text();
    EXPECT_TRUE(
        shown.startsWith(problems.last().at(0).toString() + QStringLiteral(" — Try: check that the station")))
        << shown.toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("trying again")));
}

// The waits double from a quarter of a second: from one second on they are said in seconds ("1 s",
// "2 s"), never "1000 ms".
TEST_F(ConnectionStatusTest, MainWindowSaysLongerWaitsInSeconds) {
    MainWindow window(translations);
    window.setConnection(&station);
    QSignalSpy problems(&station, &connection::StationConnection::problem);
    station.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(test::closedTcpPort()));
    const QRegularExpression inSeconds(QStringLiteral("trying again in \\d+ s "));
    ASSERT_TRUE(QTest::qWaitFor([&] { return window.passingMessage()->text().contains(inSeconds); }, 3000))
        << window.passingMessage()->text().toStdString();
    for (const QList<QVariant>& problem : problems)
        EXPECT_FALSE(problem.at(0).toString().contains(QRegularExpression(QStringLiteral("\\d{4,} ms"))))
            << problem.at(0).toString().toStdString();
}

// On a laptop's 1366 pixels, in both languages, the message about a station that cannot be reached and
// what to try is long: it takes a second line beside the station's line rather than being cut off.
TEST_F(ConnectionStatusTest, MainWindowShowsAWholeLongProblemBesideTheStationLine) {
    for (const Language language : {Language::English, Language::German}) {
        choose(language);
        MainWindow window(translations);
        window.setConnection(&station);
        window.resize(1366, 768);
        window.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
        QSignalSpy problems(&station, &connection::StationConnection::problem);
        station.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(test::closedTcpPort()));
        ASSERT_TRUE(problems.wait(test::ReadyMs));
        const PassingMessage* message = window.passingMessage();
        ASSERT_TRUE(QTest::qWaitFor([&] { return message->isWhollyShown(); }, 1000))
            << message->text().toStdString() << " is cut at " << message->width() << " px";
        EXPECT_GT(message->fontMetrics().horizontalAdvance(message->text()), message->width())
            << "the message is longer than one line here";
        const auto* line = window.findChild<QWidget*>(QStringLiteral("connectionStatus"));
        EXPECT_LE(message->mapTo(&window, QPoint(message->width(), 0)).x(),
                  line->mapTo(&window, QPoint()).x())
            << "it stays left of the station's line";
        EXPECT_LE(window.statusBar()->geometry().bottom(), window.height() - 1);
        station.disconnectFromStation();
    }
}
