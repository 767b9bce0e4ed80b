#include "shell/AboutBox.h"

#include "shell/ApplicationInfo.h"

#include <QPixmap>
#include <gtest/gtest.h>

using namespace stellwerk::ui;

TEST(AboutBox, ShowsTheProjectVersion) {
    EXPECT_EQ(applicationVersion(), QStringLiteral(STELLWERK_EXPECTED_VERSION));
    EXPECT_TRUE(AboutBox::text().contains(QStringLiteral("Stellwerk " STELLWERK_EXPECTED_VERSION)));
}

TEST(AboutBox, SaysWhatStellwerkIs) {
    EXPECT_TRUE(AboutBox::text().contains(QStringLiteral("Märklin")));
    EXPECT_TRUE(AboutBox::text().contains(QStringLiteral("Central Station")));
}

TEST(AboutBox, NamesTheQtVersions) {
    EXPECT_TRUE(AboutBox::text().contains(QStringLiteral("Built with Qt " QT_VERSION_STR)));
    EXPECT_TRUE(AboutBox::text().contains(QString::fromLatin1(qVersion())));
}

TEST(ApplicationIcon, IsEmbeddedAndRenders) {
    const QIcon icon = applicationIcon();
    ASSERT_FALSE(icon.isNull());
    // A null pixmap here means the SVG plugin (Debian: libqt6svg6) is missing.
    EXPECT_FALSE(icon.pixmap(QSize(32, 32)).isNull());
}
