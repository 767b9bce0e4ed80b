// Issue 35: the desktop's WiThrottle server is announced as `_withrottle._tcp` over mDNS exactly as
// `stellwerk-cli serve` does it (a stand-in avahi-publish-service on the PATH), and the announcement ends
// with the server; without Avahi the server runs unannounced and says why.

#include "phones/PhoneServers.h"
#include "withrottleserver/WiThrottleServer.h"

#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

namespace stellwerk::phones::test {
namespace {

// The PATH is only `dir` while this lives.
class PathIsOnly {
public:
    explicit PathIsOnly(const QString& dir) : saved_(qgetenv("PATH")) { qputenv("PATH", dir.toLocal8Bit()); }
    ~PathIsOnly() { qputenv("PATH", saved_); }
    PathIsOnly(const PathIsOnly&) = delete;
    PathIsOnly& operator=(const PathIsOnly&) = delete;

private:
    QByteArray saved_;
};

PhoneSettings withrottleOnLoopback() {
    PhoneSettings chosen;
    chosen.withrottle = true;
    chosen.withrottleListen = {QHostAddress::LocalHost, 0};
    return chosen;
}

QByteArray contents(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll().trimmed() : QByteArray();
}

bool hasText(const QString& path) {
    return QFile::exists(path) && QFileInfo(path).size() > 0;
}

TEST(PhoneServersMdns, TheWiThrottleServerIsAnnouncedWhileItRuns) {
    QTemporaryDir dir;
    const QString arguments = dir.filePath(QStringLiteral("arguments"));
    const QString ended = dir.filePath(QStringLiteral("ended"));
    QFile script(dir.filePath(QStringLiteral("avahi-publish-service")));
    ASSERT_TRUE(script.open(QIODevice::WriteOnly));
    script.write(QStringLiteral("#!/bin/sh\nPATH=/usr/bin:/bin\necho \"$@\" > '%1'\n"
                                "trap 'kill $!; echo ended > \"%2\"; exit 0' TERM\nsleep 30 &\nwait\n")
                     .arg(arguments, ended)
                     .toUtf8());
    script.close();
    script.setPermissions(script.permissions() | QFileDevice::ExeOwner);
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    PhoneServers servers(settings);
    const PathIsOnly path(dir.path());

    ASSERT_TRUE(servers.apply(withrottleOnLoopback()).isEmpty());
    ASSERT_NE(servers.withrottle(), nullptr);
    const quint16 port = servers.withrottle()->port();
    ASSERT_TRUE(QTest::qWaitFor([&] { return hasText(arguments); }, 5000))
        << servers.announcement().toStdString();
    EXPECT_EQ(contents(arguments), QStringLiteral("Stellwerk _withrottle._tcp %1").arg(port).toUtf8());
    EXPECT_TRUE(servers.announcement().contains(QStringLiteral("announced over mDNS")));
    EXPECT_FALSE(QFile::exists(ended)) << "announced as long as the server runs";

    servers.apply({});
    EXPECT_TRUE(QTest::qWaitFor([&] { return hasText(ended); }, 5000))
        << "the announcement ends with the server";
    EXPECT_TRUE(servers.announcement().isEmpty());
}

TEST(PhoneServersMdns, WithoutAvahiTheServerRunsUnannouncedAndSaysWhy) {
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    PhoneServers servers(settings);
    const PathIsOnly path(dir.path());
    ASSERT_TRUE(servers.apply(withrottleOnLoopback()).isEmpty());
    EXPECT_NE(servers.withrottle(), nullptr);
    EXPECT_TRUE(servers.announcement().contains(QStringLiteral("avahi-publish-service not found")));
}

} // namespace
} // namespace stellwerk::phones::test
