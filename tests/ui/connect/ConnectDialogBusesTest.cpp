// Further buses in Station → Connect…: listed comma-separated, checked like the station's address,
// remembered for the next start, and handed to the connection.

#include "EmbeddedStationSupport.h"
#include "ModuleBusPeer.h"
#include "connect/ConnectDialog.h"
#include "connect/StationUrlSettings.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"

#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QTest>
#include <QTimer>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

class ConnectDialogBusesTest : public ::testing::Test {
protected:
    void SetUp() override {
        settings().clear();
        ASSERT_TRUE(translations.select(Language::English));
    }
    void TearDown() override { settings().clear(); }

    static QSettings settings() {
        return QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk"));
    }
    static QLineEdit* further(const QDialog& dialog) {
        return dialog.findChild<QLineEdit*>(QStringLiteral("furtherBuses"));
    }
    static QPushButton* connectButton(const QDialog& dialog) {
        return dialog.findChild<QPushButton*>(QStringLiteral("connectButton"));
    }
    static QLabel* error(const QDialog& dialog) {
        return dialog.findChild<QLabel*>(QStringLiteral("urlError"));
    }

    Translations translations;
};

} // namespace

TEST_F(ConnectDialogBusesTest, FurtherBusesAreListedCommaSeparated) {
    ConnectDialog dialog{QString()};
    ASSERT_NE(further(dialog), nullptr);
    EXPECT_TRUE(dialog.furtherBuses().isEmpty()) << "none unless asked for";
    further(dialog)->setText(QStringLiteral(" can://socketcan/can1 ,, tcp://127.0.0.1:7000 "));
    EXPECT_EQ(dialog.furtherBuses(),
              (QStringList{QStringLiteral("can://socketcan/can1"), QStringLiteral("tcp://127.0.0.1:7000")}));
    EXPECT_TRUE(connectButton(dialog)->isEnabled());
    dialog.setFurtherBuses({QStringLiteral("can://virtualcan/can2")});
    EXPECT_EQ(further(dialog)->text(), QStringLiteral("can://virtualcan/can2"));
}

TEST_F(ConnectDialogBusesTest, AnUnreadableFurtherBusIsExplainedAndCannotBeConnected) {
    ConnectDialog dialog{QString()};
    further(dialog)->setText(QStringLiteral("can://socketcan/can1, http://modules"));
    EXPECT_FALSE(connectButton(dialog)->isEnabled());
    EXPECT_TRUE(
        error(dialog)->text().startsWith(QStringLiteral("The further bus http://modules cannot be used: ")))
        << error(dialog)->text().toStdString();
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Rejected);
    EXPECT_TRUE(StationUrlSettings::furtherBuses().isEmpty()) << "nothing stored";

    further(dialog)->setText(QStringLiteral("can://socketcan/can1"));
    EXPECT_TRUE(connectButton(dialog)->isEnabled());
    EXPECT_TRUE(error(dialog)->isHidden());
}

TEST_F(ConnectDialogBusesTest, TheStationsOwnAddressIsNoFurtherBus) {
    ConnectDialog dialog(QStringLiteral("can://socketcan/can0"));
    further(dialog)->setText(QStringLiteral("can://socketcan/can0"));
    EXPECT_FALSE(connectButton(dialog)->isEnabled());
    EXPECT_EQ(error(dialog)->text(),
              QStringLiteral("The further bus can://socketcan/can0 is the station's own address."));
}

// Connect holds the further bus open beside the station and remembers it; the next dialog offers it.
TEST_F(ConnectDialogBusesTest, ConnectOpensTheFurtherBusesAndRemembersThem) {
    support::ModuleBusPeer modules;
    ASSERT_TRUE(modules.listen());
    connection::StationConnection station{support::withEmbeddedStation()};
    MainWindow window(translations);
    window.setConnection(&station);
    QTimer::singleShot(0, &window, [&modules] {
        auto* dialog = qobject_cast<ConnectDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        EXPECT_TRUE(dialog->furtherBuses().isEmpty());
        further(*dialog)->setText(modules.url());
        connectButton(*dialog)->click();
    });
    window.findChild<QAction*>(QStringLiteral("connectAction"))->trigger();
    EXPECT_EQ(station.furtherBuses(), QStringList{modules.url()});
    ASSERT_EQ(station.buses().list().size(), 2u);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return station.buses().isBusConnected(1) && modules.hasClient(); }, 10000));
    EXPECT_EQ(StationUrlSettings::furtherBuses(), QStringList{modules.url()});

    QTimer::singleShot(0, &window, [&modules] {
        auto* dialog = qobject_cast<ConnectDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        EXPECT_EQ(dialog->furtherBuses(), QStringList{modules.url()}) << "the buses in use are offered";
        dialog->reject();
    });
    window.findChild<QAction*>(QStringLiteral("connectAction"))->trigger();
}

// docs/screenshots/connect-dialog.png and connect-dialog-de.png, with a further bus listed.
TEST_F(ConnectDialogBusesTest, SavesTheDocumentationScreenshotsWhenAsked) {
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    if (folder.isEmpty())
        GTEST_SKIP() << "set STELLWERK_SCREENSHOT_DIR to save the screenshots";
    for (const auto& [language, name] : {std::pair{Language::English, "connect-dialog.png"},
                                         std::pair{Language::German, "connect-dialog-de.png"}}) {
        ASSERT_TRUE(translations.select(language));
        ConnectDialog dialog(QStringLiteral("tcp://192.168.2.5"));
        dialog.setFurtherBuses({QStringLiteral("can://socketcan/can1")});
        dialog.show();
        QTest::qWait(50);
        EXPECT_TRUE(dialog.grab().save(folder + QLatin1Char('/') + QLatin1String(name)));
    }
    translations.select(Language::English);
}
