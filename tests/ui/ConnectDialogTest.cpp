#include "ConnectDialog.h"

#include "MainWindow.h"
#include "StationTestSupport.h"
#include "StationUrlSettings.h"
#include "Translations.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
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
        part<QCheckBox>(dialog, "useSimulatedStation")->setChecked(false);
        part<QLineEdit>(dialog, "stationUrl")->setText(url);
    }

    Translations translations;
};

} // namespace

TEST_F(ConnectDialogTest, SimulatedIsCheckedWhenNoAddressIsInUse) {
    ConnectDialog dialog{QString()};
    EXPECT_TRUE(part<QCheckBox>(dialog, "useSimulatedStation")->isChecked());
    EXPECT_FALSE(part<QLineEdit>(dialog, "stationUrl")->isEnabled());
    EXPECT_TRUE(part<QPushButton>(dialog, "connectButton")->isEnabled());
    EXPECT_EQ(dialog.url(), QString());
}

TEST_F(ConnectDialogTest, OpensWithTheAddressInUse) {
    ConnectDialog dialog(QStringLiteral("udp://192.168.2.5"));
    EXPECT_FALSE(part<QCheckBox>(dialog, "useSimulatedStation")->isChecked());
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
    part<QCheckBox>(dialog, "useSimulatedStation")->setChecked(true);
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
    EXPECT_EQ(part<QCheckBox>(dialog, "useSimulatedStation")->text(),
              QStringLiteral("&Simulierte Zentrale verwenden (Demo-Anlage)"));
    translations.select(Language::English);
}

TEST_F(ConnectDialogTest, StationMenuConnectReconnectsTheWindowsConnection) {
    connection::StationConnection station;
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
