#include "status/StatusPanel.h"

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "layout/LayoutOverview.h"
#include "model/Railway.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "shell/Workspace.h"
#include "status/GaugeWidget.h"
#include "support/StationTestSupport.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QEvent>
#include <QGroupBox>
#include <QRegularExpression>
#include <QTabWidget>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr std::uint32_t Cs2 = 0x43533201; // the simulated CS2 master
constexpr int ReadingMs = 5000;           // a poll a second; generous for a loaded machine
constexpr int CommandMs = 5000;

// The Status tab of the main window on a railway bound to the embedded simulated CS2, on screen.
class StatusPanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &window,
                         &MainWindow::setRailway);
        window.workspace()->showPanel(window.statusPanel());
        window.show();
        station.connectToSimulator();
        ASSERT_TRUE(test::waitForState(station, State::Ready));
        ASSERT_NE(railways.railway(), nullptr);
        ASSERT_TRUE(QTest::qWaitFor([this] { return panel().gauges(Cs2).size() == 4; }, ReadingMs));
    }
    void TearDown() override { translations.select(Language::English); }

    StatusPanel& panel() const { return *window.statusPanel(); }
    const model::Device& cs2() const { return *railways.railway()->device(Cs2); }
    QStringList titles() const {
        QStringList names;
        for (const GaugeWidget* gauge : panel().gauges(Cs2))
            names << gauge->title();
        return names;
    }
    bool allGaugesHaveValues() const {
        const QList<GaugeWidget*> gauges = panel().gauges(Cs2);
        return std::ranges::all_of(gauges,
                                   [](const GaugeWidget* gauge) { return gauge->value().has_value(); });
    }
    void choose(Language language) {
        ASSERT_TRUE(translations.select(language));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }

    Translations translations;
    connection::StationConnection station{support::withEmbeddedStation()};
    binding::RailwayBinding railways{station};
    MainWindow window{translations};
};

} // namespace

TEST_F(StatusPanelTest, TheStatusTabShowsTheCs2WithAGaugePerReading) {
    EXPECT_EQ(window.workspace()->dockOf(&panel())->windowTitle(), QStringLiteral("Status"));
    ASSERT_NE(panel().deviceGroup(Cs2), nullptr);
    EXPECT_EQ(panel().deviceGroup(Cs2)->title(), QStringLiteral("Central Station 2"));
    EXPECT_EQ(titles(), (QStringList{QStringLiteral("Track current (main)"),
                                     QStringLiteral("Track current (programming)"), QStringLiteral("Voltage"),
                                     QStringLiteral("Temperature")}));
    QStringList units;
    for (const GaugeWidget* gauge : panel().gauges(Cs2))
        units << gauge->unit();
    EXPECT_EQ(units, (QStringList{QStringLiteral("A"), QStringLiteral("A"), QStringLiteral("V"),
                                  QStringLiteral("°C")}));
}

TEST_F(StatusPanelTest, GaugesShowTheModelsScaledValuesWithinSeconds) {
    ASSERT_TRUE(QTest::qWaitFor([this] { return allGaugesHaveValues(); }, ReadingMs));
    const QList<GaugeWidget*> gauges = panel().gauges(Cs2);
    for (qsizetype i = 0; i < gauges.size(); ++i) {
        const model::StatusChannel& channel = cs2().channels()[std::size_t(i)];
        ASSERT_TRUE(channel.value().has_value());
        EXPECT_NEAR(*gauges[i]->value(), *channel.value(), 1e-9) << channel.name().toStdString();
        EXPECT_DOUBLE_EQ(gauges[i]->minimum(), channel.minimum());
        EXPECT_DOUBLE_EQ(gauges[i]->maximum(), channel.maximum());
    }
    // The demo's two trains draw current at about 19 V.
    EXPECT_GT(*gauges[0]->value(), 0.1);
    EXPECT_GT(*gauges[2]->value(), 15.0);
}

TEST_F(StatusPanelTest, ValuesUseTheDecimalsOfTheLabelsAndTheUnit) {
    ASSERT_TRUE(QTest::qWaitFor([this] { return allGaugesHaveValues(); }, ReadingMs));
    const QList<GaugeWidget*> gauges = panel().gauges(Cs2);
    // Labels "0.000".."4.500", "0.000".."1.000", "0.0".."25.0", "0".."90".
    EXPECT_EQ(gauges[0]->decimals(), 3);
    EXPECT_EQ(gauges[2]->decimals(), 1);
    EXPECT_EQ(gauges[3]->decimals(), 0);
    EXPECT_TRUE(
        QRegularExpression(QStringLiteral("^\\d+\\.\\d{3} A$")).match(gauges[0]->valueText()).hasMatch())
        << gauges[0]->valueText().toStdString();
    EXPECT_TRUE(QRegularExpression(QStringLiteral("^\\d+\\.\\d V$")).match(gauges[2]->valueText()).hasMatch())
        << gauges[2]->valueText().toStdString();
    EXPECT_TRUE(QRegularExpression(QStringLiteral("^\\d+ °C$")).match(gauges[3]->valueText()).hasMatch())
        << gauges[3]->valueText().toStdString();
}

TEST_F(StatusPanelTest, TheColourZonesComeFromTheRangeEnds) {
    // HGL: range ends 3000, 3500, 4000, 4500 at 10^-3 A: green to 3 A, yellow to 4 A, red to 4.5 A.
    const auto zones = cs2().channels()[0].zones();
    EXPECT_DOUBLE_EQ(zones[0].end, 3.0);
    EXPECT_DOUBLE_EQ(zones[3].end, 4.5);
    EXPECT_EQ(zones[0].green, 3);
    EXPECT_EQ(zones[0].red, 0);
    EXPECT_EQ(zones[3].red, 3);
    EXPECT_EQ(zones[3].green, 0);
}

TEST_F(StatusPanelTest, DeutschNamesTheMeasurements) {
    choose(Language::German);
    EXPECT_EQ(titles(), (QStringList{QStringLiteral("Gleisstrom Hauptgleis"),
                                     QStringLiteral("Gleisstrom Programmiergleis"),
                                     QStringLiteral("Spannung"), QStringLiteral("Temperatur")}));
    EXPECT_EQ(window.workspace()->dockOf(&panel())->windowTitle(), QStringLiteral("Status"));
    EXPECT_EQ(StatusPanel::measurementName(QStringLiteral("FOO")), QStringLiteral("FOO"));
}

TEST_F(StatusPanelTest, AnOverloadShowsTheBannerUntilThePowerIsOnAgain) {
    model::Railway& railway = *railways.railway();
    EXPECT_TRUE(panel().overloadText().isEmpty());
    emit railway.overloaded(Cs2, 1);
    EXPECT_EQ(panel().overloadText().left(54),
              QStringLiteral("Overload on Central Station 2 (Track current (main)): "));
    EXPECT_TRUE(panel().gauges(Cs2)[0]->overloaded());
    EXPECT_FALSE(panel().gauges(Cs2)[1]->overloaded());
    railway.stop();
    ASSERT_TRUE(QTest::qWaitFor([&] { return railway.power() == station::PowerState::Stopped; }, CommandMs));
    EXPECT_FALSE(panel().overloadText().isEmpty());
    railway.go();
    ASSERT_TRUE(QTest::qWaitFor([&] { return railway.power() == station::PowerState::Running; }, CommandMs));
    EXPECT_TRUE(panel().overloadText().isEmpty());
    EXPECT_FALSE(panel().gauges(Cs2)[0]->overloaded());
}

TEST_F(StatusPanelTest, ReadingsArePolledOnlyWhileTheStatusPanelIsVisible) {
    model::ReadingPoller& poller = railways.railway()->readings();
    EXPECT_TRUE(poller.running());
    window.workspace()->dockOf(&panel())->close();
    EXPECT_FALSE(poller.active());
    EXPECT_FALSE(poller.running());
    window.workspace()->showPanel(&panel());
    EXPECT_TRUE(poller.active());
    EXPECT_TRUE(poller.running());
}
