#include "connect/ConnectDialog.h"

#include "EmbeddedStationSupport.h"
#include "connect/StationUrlSettings.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "support/StationTestSupport.h"
#include "transport/CanBusTransport.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QTest>
#include <QTimer>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

QSettings stellwerkSettings() {
    return QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk"));
}

// Station → Connect… with empty settings, in English.
class ConnectDialogTest : public ::testing::Test {
protected:
    void SetUp() override {
        stellwerkSettings().clear();
        ASSERT_TRUE(translations.select(Language::English));
    }
    void TearDown() override { stellwerkSettings().clear(); }

    template <class Widget>
    static Widget* part(const QDialog& dialog, const char* name) {
        return dialog.findChild<Widget*>(QLatin1String(name));
    }
    static void enter(ConnectDialog& dialog, const QString& url) {
        part<QAbstractButton>(dialog, "useUdp")->click();
        part<QLineEdit>(dialog, "stationUrl")->setText(url);
        dialog.setUrl(url);
    }

    Translations translations;
};

} // namespace

TEST_F(ConnectDialogTest, SimulatedIsCheckedWhenNoAddressIsInUse) {
    ConnectDialog dialog{QString()};
    EXPECT_TRUE(part<QAbstractButton>(dialog, "useSimulatedStation")->isChecked());
    EXPECT_FALSE(part<QLineEdit>(dialog, "stationUrl")->isEnabled());
    EXPECT_TRUE(part<QPushButton>(dialog, "connectButton")->isEnabled());
    EXPECT_EQ(dialog.url(), QString());
}

TEST_F(ConnectDialogTest, OpensWithTheAddressInUse) {
    ConnectDialog dialog(QStringLiteral("udp://192.168.2.5"));
    EXPECT_FALSE(part<QAbstractButton>(dialog, "useSimulatedStation")->isChecked());
    EXPECT_EQ(part<QLineEdit>(dialog, "stationUrl")->text(), QStringLiteral("udp://192.168.2.5"));
    EXPECT_EQ(dialog.url(), QStringLiteral("udp://192.168.2.5"));
}

TEST_F(ConnectDialogTest, ShowsExamplesOfEveryKindOfAddress) {
    ConnectDialog dialog{QString()};
    const QString examples = part<QLabel>(dialog, "urlExamples")->text();
    EXPECT_TRUE(examples.contains(QStringLiteral("udp://192.168.2.5")));
    EXPECT_TRUE(examples.contains(QStringLiteral("tcp://192.168.2.5")));
    EXPECT_TRUE(examples.contains(QStringLiteral("can://socketcan/can0")));
}

// Issue 32: a station whose web server is not on port 80 (stellwerk-sim --http-port 8080) is named with
// `?http=8080`; the dialog takes it, and a new host keeps it.
TEST_F(ConnectDialogTest, AnAddressWithTheWebServerPortIsTakenAndKeptForANewHost) {
    ConnectDialog dialog{QString()};
    enter(dialog, QStringLiteral("tcp://127.0.0.1:15731?http=8080"));
    EXPECT_TRUE(part<QPushButton>(dialog, "connectButton")->isEnabled())
        << part<QLabel>(dialog, "urlError")->text().toStdString();
    EXPECT_TRUE(part<QAbstractButton>(dialog, "useTcp")->isChecked());
    EXPECT_EQ(part<QLineEdit>(dialog, "stationHost")->text(), QStringLiteral("127.0.0.1"));
    QLineEdit* host = part<QLineEdit>(dialog, "stationHost");
    host->clear();
    QTest::keyClicks(host, QStringLiteral("10.0.0.7"));
    EXPECT_EQ(dialog.url(), QStringLiteral("tcp://10.0.0.7:15731?http=8080"));
    EXPECT_TRUE(part<QLabel>(dialog, "urlExamples")->text().contains(QStringLiteral("?http=8080")));
}

TEST_F(ConnectDialogTest, ConnectStoresTheAddressInTheSettings) {
    ConnectDialog dialog{QString()};
    enter(dialog, QStringLiteral(" tcp://192.168.2.5 "));
    part<QPushButton>(dialog, "connectButton")->click();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(dialog.url(), QStringLiteral("tcp://192.168.2.5"));
    EXPECT_EQ(stellwerkSettings().value(QStringLiteral("station/url")).toString(),
              QStringLiteral("tcp://192.168.2.5"));
    EXPECT_EQ(StationUrlSettings::load(), QStringLiteral("tcp://192.168.2.5"));
}

TEST_F(ConnectDialogTest, SimulatedStationIsStoredAsAnEmptyAddress) {
    StationUrlSettings::save(QStringLiteral("udp://192.168.2.5"));
    ConnectDialog dialog(QStringLiteral("udp://192.168.2.5"));
    part<QAbstractButton>(dialog, "useSimulatedStation")->click();
    part<QPushButton>(dialog, "connectButton")->click();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_TRUE(stellwerkSettings().contains(QStringLiteral("station/url")));
    EXPECT_EQ(StationUrlSettings::load(), QString());
}

TEST_F(ConnectDialogTest, AnAddressThatCannotBeUsedIsExplainedAndNotStored) {
    ConnectDialog dialog{QString()};
    enter(dialog, QStringLiteral("http://cs2"));
    EXPECT_FALSE(part<QPushButton>(dialog, "connectButton")->isEnabled());
    const QString error = part<QLabel>(dialog, "urlError")->text();
    EXPECT_TRUE(error.startsWith(QStringLiteral("This address cannot be used: "))) << error.toStdString();
    dialog.accept();
    EXPECT_NE(dialog.result(), QDialog::Accepted);
    EXPECT_FALSE(stellwerkSettings().contains(QStringLiteral("station/url")));
}

TEST_F(ConnectDialogTest, CancelKeepsTheSettings) {
    StationUrlSettings::save(QStringLiteral("udp://192.168.2.5"));
    ConnectDialog dialog(QStringLiteral("udp://192.168.2.5"));
    enter(dialog, QStringLiteral("tcp://10.0.0.1"));
    dialog.reject();
    EXPECT_EQ(StationUrlSettings::load(), QStringLiteral("udp://192.168.2.5"));
}

TEST_F(ConnectDialogTest, Deutsch) {
    ASSERT_TRUE(translations.select(Language::German));
    ConnectDialog dialog{QString()};
    EXPECT_EQ(dialog.windowTitle(), QStringLiteral("Mit einer Zentrale verbinden"));
    EXPECT_EQ(part<QPushButton>(dialog, "connectButton")->text(), QStringLiteral("&Verbinden"));
    EXPECT_EQ(part<QAbstractButton>(dialog, "useSimulatedStation")->text(),
              QStringLiteral("&Simulierte Zentrale (Demo-Anlage, keine Hardware nötig)"));
    translations.select(Language::English);
}

TEST_F(ConnectDialogTest, StationMenuConnectReconnectsTheWindowsConnection) {
    connection::StationConnection station{support::withEmbeddedStation()};
    MainWindow window(translations);
    window.setConnection(&station);
    const std::uint16_t port = test::closedTcpPort();
    const QString url = QStringLiteral("tcp://127.0.0.1:%1").arg(port);
    QTimer::singleShot(0, &window, [url] {
        auto* dialog = qobject_cast<ConnectDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        enter(*dialog, url);
        part<QPushButton>(*dialog, "connectButton")->click();
    });
    window.findChild<QAction*>(QStringLiteral("connectAction"))->trigger();
    EXPECT_EQ(station.address(), url);
    EXPECT_EQ(station.state(), connection::StationConnection::State::Connecting);
    EXPECT_EQ(StationUrlSettings::load(), url);
}

TEST_F(ConnectDialogTest, StationUrlSettingsAreEmptyOnAFirstRun) {
    EXPECT_EQ(StationUrlSettings::load(), QString());
}

TEST_F(ConnectDialogTest, RecentStationsAreOfferedNewestFirstAndFillTheDialog) {
    StationUrlSettings::save(QStringLiteral("udp://192.168.2.5"));
    StationUrlSettings::save(QString());
    StationUrlSettings::save(QStringLiteral("tcp://10.0.0.7"));
    StationUrlSettings::save(QStringLiteral("udp://192.168.2.5")); // again: moves to the front, once
    ConnectDialog dialog(QStringLiteral("tcp://10.0.0.7"));
    auto* recent = part<QComboBox>(dialog, "recentStations");
    ASSERT_EQ(recent->count(), 4); // the prompt and three stations
    EXPECT_EQ(recent->itemData(1).toString(), QStringLiteral("udp://192.168.2.5"));
    EXPECT_EQ(recent->itemText(1), QStringLiteral("CS2 at 192.168.2.5 (UDP) — udp://192.168.2.5"));
    EXPECT_EQ(recent->itemData(2).toString(), QStringLiteral("tcp://10.0.0.7"));
    EXPECT_EQ(recent->itemText(3), QStringLiteral("Simulated CS2 (demo layout)"));
    recent->setCurrentIndex(1);
    emit recent->activated(1);
    EXPECT_EQ(dialog.kind(), ConnectDialog::Kind::Udp);
    EXPECT_EQ(dialog.url(), QStringLiteral("udp://192.168.2.5"));
    recent->setCurrentIndex(3);
    emit recent->activated(3);
    EXPECT_EQ(dialog.kind(), ConnectDialog::Kind::Simulated);
    EXPECT_EQ(dialog.url(), QString());
}

TEST_F(ConnectDialogTest, RecentListKeepsTheNewestEight) {
    for (int i = 1; i <= 10; ++i)
        StationUrlSettings::save(QStringLiteral("tcp://10.0.0.%1").arg(i));
    const QStringList recent = StationUrlSettings::recent();
    ASSERT_EQ(recent.size(), StationUrlSettings::MaxRecent);
    EXPECT_EQ(recent.first(), QStringLiteral("tcp://10.0.0.10"));
    EXPECT_EQ(recent.last(), QStringLiteral("tcp://10.0.0.3"));
}

TEST_F(ConnectDialogTest, AKindAndAHostMakeTheAddress) {
    ConnectDialog dialog{QString()};
    part<QAbstractButton>(dialog, "useUdp")->click();
    EXPECT_FALSE(part<QPushButton>(dialog, "connectButton")->isEnabled()); // no host yet
    QTest::keyClicks(part<QLineEdit>(dialog, "stationHost"), QStringLiteral("192.168.2.5"));
    EXPECT_EQ(dialog.url(), QStringLiteral("udp://192.168.2.5:15731")); // the ports are spelled out
    EXPECT_TRUE(part<QPushButton>(dialog, "connectButton")->isEnabled());
    part<QAbstractButton>(dialog, "useTcp")->click();
    EXPECT_EQ(dialog.url(), QStringLiteral("tcp://192.168.2.5:15731"));
}

TEST_F(ConnectDialogTest, ATypedAddressPicksItsKindAndKeepsItsPortWhenTheHostChanges) {
    ConnectDialog dialog{QString()};
    part<QAbstractButton>(dialog, "useUdp")->click();
    QLineEdit* address = part<QLineEdit>(dialog, "stationUrl");
    address->clear();
    QTest::keyClicks(address, QStringLiteral("tcp://10.0.0.1:15732"));
    EXPECT_EQ(dialog.kind(), ConnectDialog::Kind::Tcp);
    EXPECT_EQ(part<QLineEdit>(dialog, "stationHost")->text(), QStringLiteral("10.0.0.1"));
    QLineEdit* host = part<QLineEdit>(dialog, "stationHost");
    host->selectAll();
    QTest::keyClicks(host, QStringLiteral("10.0.0.2"));
    EXPECT_EQ(dialog.url(), QStringLiteral("tcp://10.0.0.2:15732"));
}

TEST_F(ConnectDialogTest, CanInterfacesAreTheOnesThePluginsOffer) {
    ConnectDialog dialog{QString()};
    auto* interfaces = part<QComboBox>(dialog, "canInterface");
    QStringList offered;
    for (const transport::CanBusInterface& found : transport::CanBusTransport::availableInterfaces())
        offered << found.plugin + QLatin1Char('/') + found.name;
    QStringList listed;
    for (int i = 0; i < interfaces->count(); ++i)
        listed << interfaces->itemText(i);
    EXPECT_EQ(listed, offered);
    part<QAbstractButton>(dialog, "useCan")->click();
    interfaces->setCurrentText(QStringLiteral("virtualcan/can1"));
    EXPECT_EQ(dialog.kind(), ConnectDialog::Kind::CanBus);
    EXPECT_EQ(dialog.url(), QStringLiteral("can://virtualcan/can1"));
    EXPECT_TRUE(part<QPushButton>(dialog, "connectButton")->isEnabled());
}

TEST_F(ConnectDialogTest, TheSimulatedStationKeepsTheTypedAddressForLater) {
    ConnectDialog dialog(QStringLiteral("udp://192.168.2.5"));
    part<QAbstractButton>(dialog, "useSimulatedStation")->click();
    EXPECT_EQ(dialog.url(), QString());
    EXPECT_FALSE(part<QLineEdit>(dialog, "stationHost")->isEnabled());
    part<QAbstractButton>(dialog, "useUdp")->click();
    EXPECT_EQ(dialog.url(), QStringLiteral("udp://192.168.2.5:15731"));
}
