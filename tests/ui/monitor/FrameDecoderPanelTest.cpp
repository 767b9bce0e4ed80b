#include "monitor/FrameDecoderPanel.h"

#include "shell/Translations.h"

#include <QCoreApplication>
#include <QLabel>
#include <QPlainTextEdit>
#include <QTest>
#include <QTreeWidget>
#include <gtest/gtest.h>

using namespace stellwerk::ui;

namespace {

QTreeWidget* results(FrameDecoderPanel& panel) {
    return panel.findChild<QTreeWidget*>(QStringLiteral("frameResults"));
}

QString summary(FrameDecoderPanel& panel) {
    return panel.findChild<QLabel*>(QStringLiteral("decoderSummary"))->text();
}

// English installed explicitly, so that plural forms are real ("1 frame", "2 frames").
class FrameDecoderPanelTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(translations.select(Language::English)); }
    Translations translations;
};

} // namespace

TEST_F(FrameDecoderPanelTest, DecodesEachPastedLineIntoARow) {
    FrameDecoderPanel panel;
    panel.setInput(QStringLiteral("# from the document\n"
                                  "00084711 6 00 00 C0 03 01 20\n"
                                  "\n"
                                  "00314711#4743F5DA013E0010\n"));
    QTreeWidget* table = results(panel);
    ASSERT_EQ(table->topLevelItemCount(), 2);
    const QTreeWidgetItem* speed = table->topLevelItem(0);
    EXPECT_EQ(speed->text(0), QStringLiteral("2"));
    EXPECT_EQ(speed->text(1), QStringLiteral("00084711 6 00 00 C0 03 01 20"));
    EXPECT_EQ(speed->text(2), QStringLiteral("loco.speed"));
    EXPECT_EQ(speed->text(3), QStringLiteral("locId=0xC003 protocol=dcc address=3 speed=288"));
    const QTreeWidgetItem* ping = table->topLevelItem(1);
    EXPECT_EQ(ping->text(0), QStringLiteral("4"));
    EXPECT_EQ(ping->text(2), QStringLiteral("ping (response)")) << "responses are marked";
    EXPECT_EQ(summary(panel), QStringLiteral("2 frames"));
}

TEST_F(FrameDecoderPanelTest, ShowsUnreadableAndInvalidFramesWithTheirReason) {
    FrameDecoderPanel panel;
    panel.setInput(QStringLiteral("00084711 5 00 00 C0 03 01\nhello\n00004711 5 00 00 00 00 01"));
    QTreeWidget* table = results(panel);
    ASSERT_EQ(table->topLevelItemCount(), 3);
    EXPECT_EQ(table->topLevelItem(0)->text(2), QStringLiteral("loco.speed"));
    EXPECT_EQ(table->topLevelItem(0)->text(3),
              QStringLiteral("unexpected length 5: loco.speed has 4 (query) or 6 data bytes"));
    EXPECT_EQ(table->topLevelItem(1)->text(2), QStringLiteral("unreadable"));
    EXPECT_EQ(table->topLevelItem(1)->text(3), QStringLiteral("'hello' is not a hexadecimal CAN identifier"));
    EXPECT_NE(table->topLevelItem(1)->foreground(3).color(), table->topLevelItem(2)->foreground(3).color())
        << "errors stand out";
    EXPECT_EQ(table->topLevelItem(2)->text(2), QStringLiteral("system.go"));
    EXPECT_EQ(summary(panel), QStringLiteral("3 frames, 2 not decodable"));
}

TEST_F(FrameDecoderPanelTest, DecodesShortlyAfterTypingStops) {
    FrameDecoderPanel panel;
    auto* input = panel.findChild<QPlainTextEdit*>(QStringLiteral("frameInput"));
    input->setPlainText(QStringLiteral("00004711 5 00 00 00 00 00"));
    EXPECT_EQ(results(panel)->topLevelItemCount(), 0) << "not on every key press";
    EXPECT_TRUE(QTest::qWaitFor([&] { return results(panel)->topLevelItemCount() == 1; }, 2000));
    EXPECT_EQ(results(panel)->topLevelItem(0)->text(2), QStringLiteral("system.stop"));
}

TEST_F(FrameDecoderPanelTest, EmptyInputGivesAnEmptyTable) {
    FrameDecoderPanel panel;
    panel.setInput(QString());
    EXPECT_EQ(results(panel)->topLevelItemCount(), 0);
    EXPECT_EQ(summary(panel), QStringLiteral("0 frames"));
    panel.setInput(QStringLiteral("00004711 5 00 00 00 00 00"));
    EXPECT_EQ(summary(panel), QStringLiteral("1 frame"));
}

TEST_F(FrameDecoderPanelTest, SummaryFollowsALanguageChange) {
    FrameDecoderPanel panel;
    panel.setInput(QStringLiteral("00004711 5 00 00 00 00 00\n00004711 5 00 00 00 00 01"));
    ASSERT_TRUE(translations.select(Language::German));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_EQ(summary(panel), QStringLiteral("2 Telegramme"));
    ASSERT_TRUE(translations.select(Language::English));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_EQ(summary(panel), QStringLiteral("2 frames"));
}
