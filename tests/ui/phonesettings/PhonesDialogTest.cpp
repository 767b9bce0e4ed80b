// Issue 35: Station → Phones… writes the phone settings and starts the servers at once on a free loopback
// port; Escape changes nothing; the status bar counts the phones of a real Z21 client on loopback. The dialog
// in English and German, its whole text shown on a 1366x768 screen (saved as
// docs/screenshots/phones-dialog*.png when STELLWERK_SCREENSHOT_DIR names a folder).

#include "phonesettings/PhonesDialog.h"

#include "../../core/z21server/Z21TestClient.h"
#include "phones/PhoneServers.h"
#include "phonesettings/PhoneStatus.h"
#include "shell/Translations.h"
#include "z21server/Z21Server.h"

#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QSettings>
#include <QSpinBox>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>
#include <gtest/gtest.h>

namespace stellwerk::ui::test {
namespace {

// A UDP port no one uses now, as the system gives it.
quint16 freeUdpPort() {
    QUdpSocket probe;
    probe.bind(QHostAddress::LocalHost, 0);
    return probe.localPort();
}

quint16 freeTcpPort() {
    QTcpServer probe;
    probe.listen(QHostAddress::LocalHost, 0);
    return probe.serverPort();
}

class PhonesDialogTest : public ::testing::Test {
protected:
    QTemporaryDir dir;
    QSettings settings{dir.filePath(QStringLiteral("phones.ini")), QSettings::IniFormat};
    phones::PhoneServers servers{settings};

    template <class T>
    T* field(PhonesDialog& dialog, const char* name) {
        return dialog.findChild<T*>(QString::fromLatin1(name));
    }
};

TEST_F(PhonesDialogTest, BothServersAreOffByDefault) {
    EXPECT_FALSE(phones::PhoneSettings::load(settings).anyOn());
    PhonesDialog dialog(servers);
    EXPECT_FALSE(field<QCheckBox>(dialog, "z21On")->isChecked());
    EXPECT_FALSE(field<QCheckBox>(dialog, "withrottleOn")->isChecked());
    EXPECT_EQ(field<QSpinBox>(dialog, "z21Port")->value(), 21105);
    EXPECT_EQ(field<QSpinBox>(dialog, "withrottlePort")->value(), 12090);
}

TEST_F(PhonesDialogTest, OkWritesTheSettingsAndStartsTheServerOnItsPort) {
    const quint16 z21Port = freeUdpPort();
    const quint16 wiPort = freeTcpPort();
    PhonesDialog dialog(servers);
    field<QCheckBox>(dialog, "z21On")->setChecked(true);
    field<QLineEdit>(dialog, "z21Address")->setText(QStringLiteral("127.0.0.1"));
    field<QSpinBox>(dialog, "z21Port")->setValue(z21Port);
    field<QCheckBox>(dialog, "withrottleOn")->setChecked(true);
    field<QLineEdit>(dialog, "withrottleAddress")->setText(QStringLiteral("127.0.0.1"));
    field<QSpinBox>(dialog, "withrottlePort")->setValue(wiPort);
    field<QLineEdit>(dialog, "allowedClients")->setText(QStringLiteral("127.0.0.1, 127.0.0.2"));
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);

    ASSERT_NE(servers.z21(), nullptr);
    EXPECT_EQ(servers.z21()->port(), z21Port);
    ASSERT_NE(servers.withrottle(), nullptr);
    QUdpSocket taken;
    EXPECT_FALSE(taken.bind(QHostAddress::LocalHost, z21Port)) << "the Z21 server holds its port";
    const phones::PhoneSettings saved = phones::PhoneSettings::load(settings);
    EXPECT_TRUE(saved.z21);
    EXPECT_EQ(saved.z21Listen.port, z21Port);
    EXPECT_EQ(saved.z21Listen.address, QHostAddress(QHostAddress::LocalHost));
    EXPECT_TRUE(saved.withrottle);
    EXPECT_EQ(saved.withrottleListen.port, wiPort);
    EXPECT_EQ(saved.allowedClients.size(), 2);
    EXPECT_EQ(saved, servers.settings());
}

TEST_F(PhonesDialogTest, EscapeChangesNothing) {
    PhonesDialog dialog(servers);
    dialog.show();
    field<QCheckBox>(dialog, "z21On")->setChecked(true);
    QTest::keyClick(&dialog, Qt::Key_Escape);
    EXPECT_EQ(dialog.result(), QDialog::Rejected);
    EXPECT_FALSE(servers.running());
    EXPECT_FALSE(settings.contains(QStringLiteral("phones/z21")));
}

TEST_F(PhonesDialogTest, AnAddressThatIsNoneIsRefusedWithASentence) {
    PhonesDialog dialog(servers);
    field<QCheckBox>(dialog, "z21On")->setChecked(true);
    field<QLineEdit>(dialog, "z21Address")->setText(QStringLiteral("my computer"));
    dialog.accept();
    EXPECT_NE(dialog.result(), QDialog::Accepted);
    EXPECT_FALSE(servers.running());
    EXPECT_TRUE(field<QLabel>(dialog, "phonesProblem")->text().contains(QStringLiteral("my computer")));
}

TEST_F(PhonesDialogTest, TheStatusBarCountsTheConnectedPhones) {
    PhoneStatus status;
    status.setPhoneServers(&servers);
    EXPECT_TRUE(status.isHidden()) << "no server runs";
    phones::PhoneSettings chosen;
    chosen.z21 = true;
    chosen.z21Listen = {QHostAddress::LocalHost, 0};
    ASSERT_TRUE(servers.apply(chosen).isEmpty());
    EXPECT_FALSE(status.isHidden());
    EXPECT_EQ(status.text(), QStringLiteral("Phones: 0"));

    z21server::test::Z21TestClient phone(servers.z21()->port());
    phone.send(z21::GetSerialNumber{});
    ASSERT_TRUE(phone.waitFor<z21::SerialNumber>());
    EXPECT_TRUE(QTest::qWaitFor([&] { return status.text() == QStringLiteral("Phones: 1"); }));
    EXPECT_TRUE(status.toolTip().contains(QString::number(phone.localPort())));
    phone.send(z21::Logoff{});
    EXPECT_TRUE(QTest::qWaitFor([&] { return status.text() == QStringLiteral("Phones: 0"); }));

    servers.apply({});
    EXPECT_TRUE(status.isHidden());
}

// Both servers on with a list of allowed phones, as a user fills it in: every label is shown whole (none is
// narrower than its text) and the dialog fits a 1366x768 screen, in both languages.
TEST_F(PhonesDialogTest, FitsASmallScreenInEnglishAndGerman) {
    phones::PhoneSettings chosen;
    chosen.z21 = true;
    chosen.withrottle = true;
    chosen.allowedClients = {QHostAddress(QStringLiteral("192.168.1.30")),
                             QHostAddress(QStringLiteral("192.168.1.31"))};
    chosen.z21Listen = {QHostAddress::LocalHost, freeUdpPort()};
    chosen.withrottleListen = {QHostAddress::LocalHost, freeTcpPort()};
    ASSERT_TRUE(servers.apply(chosen).isEmpty()) << "both servers run, as the dialog then shows them";
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    Translations translations;
    for (const Language language : {Language::English, Language::German}) {
        ASSERT_TRUE(translations.select(language));
        PhonesDialog dialog(servers);
        dialog.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
        EXPECT_LE(dialog.width(), 1366 * 2 / 3) << "a dialog, not a window";
        EXPECT_LE(dialog.height(), 768 - 80) << "fits under a panel and title bar";
        for (const QLabel* label : dialog.findChildren<QLabel*>()) {
            if (!label->isVisible() || label->wordWrap() || label->text().isEmpty())
                continue;
            EXPECT_GE(label->width(), label->fontMetrics().horizontalAdvance(label->text()) - 2)
                << label->text().toStdString() << " is cut off";
        }
        const auto* clients = field<QLineEdit>(dialog, "allowedClients");
        EXPECT_GE(clients->width(),
                  clients->fontMetrics().horizontalAdvance(QStringLiteral("192.168.1.30, 192.168.1.31")))
            << "two allowed addresses are seen whole";
        EXPECT_GE(clients->width(), clients->fontMetrics().horizontalAdvance(clients->placeholderText()));
        if (language == Language::German) {
            EXPECT_EQ(dialog.windowTitle(), QStringLiteral("Handys und Tablets"));
        }
        if (!folder.isEmpty()) {
            const QString suffix = language == Language::German ? QStringLiteral("-de") : QString();
            EXPECT_TRUE(dialog.grab().save(folder + QStringLiteral("/phones-dialog%1.png").arg(suffix)));
        }
    }
}

} // namespace
} // namespace stellwerk::ui::test
