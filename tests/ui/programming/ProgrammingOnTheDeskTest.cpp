// The programming panel inside the desk: registering a new mfx decoder leaves the panel where it is (in
// front, scrolled as it was, the decoder's row still shown) and its instruction text says what happened
// and what to do next; the texts follow a language switch.

#include "programming/ProgrammingPanel.h"
#include "shell/Workspace.h"
#include "support/TrustTestSupport.h"

#include <QApplication>
#include <QDockWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QTableWidget>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

constexpr int AnswerMs = 5000;

class ProgrammingOnTheDeskTest : public test::DeskOnTestStation {
protected:
    void SetUp() override {
        DeskOnTestStation::SetUp();
        ASSERT_TRUE(window->workspace()->showPanel(panel()));
        QTest::qWait(50);
    }
    ProgrammingPanel* panel() const { return window->programmingPanel(); }
    QDockWidget* dock() const { return window->workspace()->dockOf(panel()); }
    QString decoderState() const {
        const QTableWidgetItem* item = panel()->decoderTable()->item(0, 1);
        return item ? item->text() : QString();
    }
    bool searchAndRegister() {
        panel()->searchButton()->click();
        if (!QTest::qWaitFor([this] { return panel()->decoderTable()->rowCount() == 1; }, AnswerMs))
            return false;
        panel()->registerButton()->click();
        return QTest::qWaitFor([this] { return decoderState().startsWith(QStringLiteral("registered")); },
                               AnswerMs);
    }
};

} // namespace

TEST_F(ProgrammingOnTheDeskTest, RegisteringLeavesThePanelWhereItIsAndSaysWhatHappened) {
    auto* scroll = dock()->findChild<QScrollArea*>(QStringLiteral("programmingPanelScroll"));
    ASSERT_NE(scroll, nullptr);
    const QPoint placed = panel()->mapTo(window.get(), QPoint());
    const int scrolled = scroll->verticalScrollBar()->value();
    ASSERT_TRUE(searchAndRegister()) << decoderState().toStdString();
    QTest::qWait(100);
    EXPECT_FALSE(dock()->visibleRegion().isEmpty()) << "still in front of its tab";
    EXPECT_EQ(panel()->mapTo(window.get(), QPoint()), placed);
    EXPECT_EQ(scroll->verticalScrollBar()->value(), scrolled);
    EXPECT_EQ(panel()->decoderTable()->rowCount(), 1) << "the registered decoder stays in the list";
    EXPECT_TRUE(
        panel()->searchText().startsWith(QStringLiteral("Registered mfx decoder 0x7a3c1e10 on SID 6")))
        << panel()->searchText().toStdString();
}

TEST_F(ProgrammingOnTheDeskTest, TheInstructionAndTheDecoderStateFollowALanguageSwitch) {
    ASSERT_TRUE(searchAndRegister());
    ASSERT_TRUE(translations.select(Language::German));
    QApplication::processEvents(); // the widgets hear of the new language by a posted event
    EXPECT_TRUE(
        panel()->searchText().startsWith(QStringLiteral("mfx-Decoder 0x7a3c1e10 auf SID 6 angemeldet")))
        << panel()->searchText().toStdString();
    EXPECT_EQ(decoderState(), QStringLiteral("unter SID 6 angemeldet"));
    ASSERT_TRUE(translations.select(Language::English));
    QApplication::processEvents();
    EXPECT_EQ(decoderState(), QStringLiteral("registered on SID 6"));
}
