// The mDNS announcement of the WiThrottle server: avahi-publish-service is run with the service type and port
// where it exists, and nothing is run (with a reason for the log) where it does not.

#include "withrottleserver/MdnsAnnouncement.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

namespace stellwerk::withrottleserver::test {
namespace {

TEST(MdnsAnnouncement, WithoutAvahiNothingIsAnnouncedAndTheLogSaysWhy) {
    QTemporaryDir empty;
    MdnsAnnouncement announcement({empty.path()});
    EXPECT_FALSE(announcement.announce(QStringLiteral("Stellwerk"), 12090));
    EXPECT_TRUE(announcement.why().contains(QStringLiteral("avahi-publish-service not found")));
}

TEST(MdnsAnnouncement, AvahiPublishServiceIsRunWithTheServiceTypeAndPort) {
    QTemporaryDir dir;
    const QString seen = dir.filePath(QStringLiteral("arguments"));
    QFile script(dir.filePath(QStringLiteral("avahi-publish-service")));
    ASSERT_TRUE(script.open(QIODevice::WriteOnly));
    script.write(QStringLiteral("#!/bin/sh\necho \"$@\" > '%1'\nexec sleep 30\n").arg(seen).toUtf8());
    script.close();
    script.setPermissions(script.permissions() | QFileDevice::ExeOwner);
    {
        MdnsAnnouncement announcement({dir.path()});
        ASSERT_TRUE(announcement.announce(QStringLiteral("Stellwerk"), 12345))
            << announcement.why().toStdString();
        ASSERT_TRUE(QTest::qWaitFor([&] { return QFile::exists(seen) && QFileInfo(seen).size() > 0; }, 5000));
    }
    QFile arguments(seen);
    ASSERT_TRUE(arguments.open(QIODevice::ReadOnly));
    EXPECT_EQ(arguments.readAll().trimmed(), QByteArray("Stellwerk _withrottle._tcp 12345"));
}

} // namespace
} // namespace stellwerk::withrottleserver::test
