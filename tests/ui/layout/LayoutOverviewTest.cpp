#include "layout/LayoutOverview.h"

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "common/LocomotiveTableModel.h"
#include "layout/ContactTableModel.h"
#include "model/Railway.h"
#include "monitor/BusMonitorPanel.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "shell/Workspace.h"
#include "support/StationTestSupport.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QEvent>
#include <QSignalSpy>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

// The demo trains change a contact every second or two; generous for a loaded machine.
constexpr int MovementMs = 15000;
constexpr int CommandMs = 5000;

constexpr quint32 V100 = 0x18; // V 100 2023, MM2 address 24: stands still in the demo

// The Layout page on a railway bound to the embedded simulated CS2 (the app's default), ready to look at.
class LayoutOverviewTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &overview,
                         &LayoutOverview::setRailway);
        station.connectToSimulator();
        ASSERT_TRUE(test::waitForState(station, State::Ready));
        ASSERT_NE(railways.railway(), nullptr);
    }
    void TearDown() override { translations.select(Language::English); }

    void choose(Language language) {
        ASSERT_TRUE(translations.select(language));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
    static QString cell(const QAbstractItemModel& model, int row, int column) {
        return model.index(row, column).data().toString();
    }
    static QString header(const QAbstractItemModel& model, int column) {
        return model.headerData(column, Qt::Horizontal).toString();
    }
    QStringList column(const QAbstractItemModel& model, int column) const {
        QStringList texts;
        for (int row = 0; row < model.rowCount(); ++row)
            texts << cell(model, row, column);
        return texts;
    }

    Translations translations;
    connection::StationConnection station{support::withEmbeddedStation()};
    binding::RailwayBinding railways{station};
    LayoutOverview overview;
};

} // namespace

TEST_F(LayoutOverviewTest, ListsTheDemosTwelveLocomotivesWithTheirAddresses) {
    const LocomotiveTableModel& locos = *overview.locomotives();
    ASSERT_EQ(locos.rowCount(), 12);
    const QStringList names = column(locos, LocomotiveTableModel::Name);
    EXPECT_TRUE(names.contains(QStringLiteral("BR 218 Ost")));
    EXPECT_TRUE(names.contains(QStringLiteral("Köf III")));
    const int v100 = locos.rowOf(V100).value_or(-1);
    ASSERT_GE(v100, 0);
    EXPECT_EQ(cell(locos, v100, LocomotiveTableModel::Name), QStringLiteral("V 100 2023"));
    EXPECT_EQ(cell(locos, v100, LocomotiveTableModel::Address), QStringLiteral("MM2 24"));
    EXPECT_EQ(cell(locos, v100, LocomotiveTableModel::Speed), QStringLiteral("0 %"));
    EXPECT_EQ(cell(locos, v100, LocomotiveTableModel::Direction), QStringLiteral("forward"));
}

TEST_F(LayoutOverviewTest, TheEmbeddedDemoRunsTwoTrainsWithTheLightsOn) {
    const LocomotiveTableModel& locos = *overview.locomotives();
    QStringList running;
    for (int row = 0; row < locos.rowCount(); ++row)
        if (cell(locos, row, LocomotiveTableModel::Speed) != QStringLiteral("0 %")) {
            running << cell(locos, row, LocomotiveTableModel::Name);
            EXPECT_TRUE(cell(locos, row, LocomotiveTableModel::Functions).startsWith(QStringLiteral("F0")));
        }
    EXPECT_EQ(running, (QStringList{QStringLiteral("BR 218 Ost"), QStringLiteral("ICE 3 Velaro")}));
}

TEST_F(LayoutOverviewTest, ListsTheDemosFeedbackContactsInNumberOrder) {
    const ContactTableModel& contacts = *overview.contacts();
    ASSERT_EQ(contacts.rowCount(), 9);
    EXPECT_EQ(column(contacts, ContactTableModel::Number),
              (QStringList{"1", "2", "3", "4", "5", "6", "7", "8", "9"}));
    EXPECT_EQ(cell(contacts, 0, ContactTableModel::Name), QStringLiteral("Gleis 1"));
    // The trains stand on Gleis 1 and 2, Block 2 and the siding when the station starts; BR 218 leaves Gleis
    // 1's contact within a second, the V 100 stays on Gleis 2's.
    EXPECT_EQ(cell(contacts, 1, ContactTableModel::State), QStringLiteral("occupied"));
    EXPECT_FALSE(contacts.index(1, ContactTableModel::State).data(Qt::DecorationRole).isNull());
}

// Which train is on an occupied contact, as the simulator or the user says (the plan shows it too).
TEST_F(LayoutOverviewTest, AnOccupiedContactNamesTheLocomotiveOnIt) {
    const ContactTableModel& contacts = *overview.contacts();
    ASSERT_EQ(cell(contacts, 1, ContactTableModel::State),
              QStringLiteral("occupied")); // the V 100 on Gleis 2
    EXPECT_EQ(cell(contacts, 1, ContactTableModel::Locomotive), QString()) << "nobody said";
    QSignalSpy changed(&contacts, &QAbstractItemModel::dataChanged);
    railways.railway()->reportOccupant(model::contactKey(0, 2), V100);
    EXPECT_EQ(cell(contacts, 1, ContactTableModel::Locomotive), QStringLiteral("V 100 2023"));
    EXPECT_EQ(changed.count(), 1) << "the row is told, without a reset";
    EXPECT_EQ(header(contacts, ContactTableModel::Locomotive), QStringLiteral("Locomotive"));
    // Einfahrt West (7): the running trains need many seconds to reach it.
    ASSERT_EQ(cell(contacts, 6, ContactTableModel::State), QStringLiteral("free"));
    railways.railway()->reportOccupant(model::contactKey(0, 7), 0x4001);
    EXPECT_EQ(cell(contacts, 6, ContactTableModel::Locomotive), QString())
        << "a free contact has nobody on it";
}

TEST_F(LayoutOverviewTest, TrackPowerIsOnInTheEmbeddedDemo) {
    EXPECT_TRUE(QTest::qWaitFor([this] { return railways.railway()->power().has_value(); }, CommandMs));
    EXPECT_EQ(overview.powerText(), QStringLiteral("Track power: on, trains may run"));
}

TEST_F(LayoutOverviewTest, AContactChangesAsTheTrainsMoveWithoutAModelReset) {
    const ContactTableModel& contacts = *overview.contacts();
    const QStringList before = column(contacts, ContactTableModel::State);
    QSignalSpy resets(&contacts, &QAbstractItemModel::modelReset);
    QSignalSpy changes(&contacts, &QAbstractItemModel::dataChanged);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return column(contacts, ContactTableModel::State) != before; }, MovementMs));
    EXPECT_GE(changes.count(), 1);
    EXPECT_EQ(resets.count(), 0);
    EXPECT_EQ(contacts.rowCount(), 9);
}

TEST_F(LayoutOverviewTest, ASpeedSetThroughTheRailwayShowsInTheTable) {
    const LocomotiveTableModel& locos = *overview.locomotives();
    const int v100 = locos.rowOf(V100).value_or(-1);
    ASSERT_GE(v100, 0);
    QSignalSpy resets(&locos, &QAbstractItemModel::modelReset);
    QSignalSpy changes(&locos, &QAbstractItemModel::dataChanged);
    railways.railway()->setSpeed(V100, 500);
    EXPECT_TRUE(QTest::qWaitFor(
        [&] { return cell(locos, v100, LocomotiveTableModel::Speed) == QStringLiteral("50 %"); }, CommandMs));
    ASSERT_GE(changes.count(), 1);
    EXPECT_LE(changes.first().at(0).value<QModelIndex>().row(), v100);
    EXPECT_GE(changes.first().at(1).value<QModelIndex>().row(), v100);
    EXPECT_EQ(resets.count(), 0);
}

TEST_F(LayoutOverviewTest, DeutschTranslatesHeadersStatesAndPower) {
    ASSERT_TRUE(QTest::qWaitFor([this] { return railways.railway()->power().has_value(); }, CommandMs));
    choose(Language::German);
    const LocomotiveTableModel& locos = *overview.locomotives();
    EXPECT_EQ(header(locos, LocomotiveTableModel::Name), QStringLiteral("Lok"));
    EXPECT_EQ(header(locos, LocomotiveTableModel::Address), QStringLiteral("Adresse"));
    EXPECT_EQ(header(locos, LocomotiveTableModel::Speed), QStringLiteral("Geschwindigkeit"));
    EXPECT_EQ(header(locos, LocomotiveTableModel::Direction), QStringLiteral("Richtung"));
    EXPECT_EQ(header(locos, LocomotiveTableModel::Functions), QStringLiteral("Funktionen an"));
    const ContactTableModel& contacts = *overview.contacts();
    EXPECT_EQ(header(contacts, ContactTableModel::Number), QStringLiteral("Kontakt"));
    EXPECT_EQ(header(contacts, ContactTableModel::State), QStringLiteral("Zustand"));
    EXPECT_EQ(header(contacts, ContactTableModel::LastChange), QStringLiteral("Letzte Änderung"));
    EXPECT_EQ(header(contacts, ContactTableModel::Locomotive), QStringLiteral("Lok"));
    EXPECT_EQ(cell(contacts, 0, ContactTableModel::State), QStringLiteral("besetzt"));
    EXPECT_EQ(overview.powerText(), QStringLiteral("Gleisspannung: an, Züge dürfen fahren"));
}

TEST_F(LayoutOverviewTest, DisconnectingEmptiesTheTables) {
    station.disconnectFromStation();
    EXPECT_EQ(railways.railway(), nullptr);
    EXPECT_EQ(overview.locomotives()->rowCount(), 0);
    EXPECT_EQ(overview.contacts()->rowCount(), 0);
    EXPECT_EQ(overview.powerText(), QStringLiteral("No station connected"));
}

TEST(LayoutOverviewInTheWindow, IsAPanelInFrontOfTheBusTools) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    MainWindow window(translations);
    window.show();
    QDockWidget* dock = window.workspace()->dockOf(window.layoutOverview());
    ASSERT_NE(dock, nullptr);
    EXPECT_EQ(dock->windowTitle(), QStringLiteral("Overview"));
    EXPECT_TRUE(window.layoutOverview()->isVisible());
    EXPECT_FALSE(window.busMonitor()->isVisible()); // stacked behind the overview
}
