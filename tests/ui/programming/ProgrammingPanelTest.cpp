// The Programming page on the embedded simulated CS2: mfx search with progress, registration on a free
// SID (and the new locomotive on the Locomotives page), CV write and read, what MM2 cannot do.

#include "programming/ProgrammingPanel.h"

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "common/LocomotivePictureBook.h"
#include "locomotives/LocomotiveFileModel.h"
#include "locomotives/LocomotivePanel.h"
#include "model/Railway.h"
#include "shell/Translations.h"
#include "support/StationTestSupport.h"

#include <QApplication>
#include <QComboBox>
#include <QPalette>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr int AnswerMs = 5000;

class ProgrammingPanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &panel,
                         &ProgrammingPanel::setRailway);
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &locomotives,
                         &LocomotivePanel::setRailway);
        QObject::connect(&panel, &ProgrammingPanel::decoderBound, &locomotives,
                         &LocomotivePanel::addBoundDecoder);
        station.connectToSimulator();
        ASSERT_TRUE(test::waitForState(station, State::Ready));
        ASSERT_NE(railways.railway(), nullptr);
    }
    bool waitForResult(const QString& start) {
        return QTest::qWaitFor([&] { return panel.resultText().startsWith(start); }, AnswerMs);
    }
    bool search() {
        panel.searchButton()->click();
        return QTest::qWaitFor([this] { return panel.decoderTable()->rowCount() == 1; }, AnswerMs);
    }
    QString decoderState() const {
        const QTableWidgetItem* item = panel.decoderTable()->item(0, 1);
        return item ? item->text() : QString();
    }

    Translations translations;
    connection::StationConnection station{support::withEmbeddedStation()};
    binding::RailwayBinding railways{station};
    ProgrammingPanel panel;
    LocomotivePanel locomotives;
};

} // namespace

TEST_F(ProgrammingPanelTest, TheSearchShowsItsProgressAndFindsTheNewDecoder) {
    QSignalSpy steps(panel.searchProgress(), &QProgressBar::valueChanged);
    ASSERT_TRUE(search());
    EXPECT_GE(steps.count(), 2) << "the station's search steps move the bar";
    EXPECT_EQ(panel.searchProgress()->value(), panel.searchProgress()->maximum());
    EXPECT_EQ(panel.decoderTable()->item(0, 0)->text(), QStringLiteral("0x7a3c1e10"));
    EXPECT_EQ(decoderState(), QStringLiteral("found"));
    EXPECT_TRUE(panel.searchText().startsWith(QStringLiteral("Found mfx decoder 0x7a3c1e10")));
    EXPECT_EQ(panel.sidBox()->value(), 6) << "the demo's mfx locomotives use SIDs 1 to 5";
}

TEST_F(ProgrammingPanelTest, ARegisteredDecoderAppearsAsALocomotive) {
    ASSERT_TRUE(search());
    ASSERT_TRUE(panel.registerButton()->isEnabled());
    panel.registerButton()->click();
    ASSERT_TRUE(
        QTest::qWaitFor([this] { return decoderState() == QStringLiteral("registered on SID 6"); }, AnswerMs))
        << decoderState().toStdString();
    const model::Locomotive* added = railways.railway()->locomotive(0x4006);
    ASSERT_NE(added, nullptr);
    EXPECT_EQ(added->name(), QStringLiteral("mfx 7a3c1e10"));
    EXPECT_EQ(locomotives.model()->rowCount(), 13);
    EXPECT_EQ(panel.sidBox()->value(), 7);
    // Registered decoders take no part in the next search.
    panel.searchButton()->click();
    EXPECT_TRUE(QTest::qWaitFor(
        [this] { return panel.searchText().startsWith(QStringLiteral("No new mfx decoder")); }, AnswerMs));
}

TEST_F(ProgrammingPanelTest, ACvWrittenToADccDecoderIsReadBack) {
    ASSERT_TRUE(panel.chooseLocomotive(QStringLiteral("BR 212 DB")));
    EXPECT_EQ(panel.protocolBox()->currentText(), QStringLiteral("DCC"));
    EXPECT_EQ(panel.addressBox()->value(), 3);
    panel.cvBox()->setValue(3);
    panel.valueBox()->setValue(42);
    panel.writeButton()->click();
    ASSERT_TRUE(waitForResult(QStringLiteral("CV 3 written: 42, read back and verified.")))
        << panel.resultText().toStdString();
    panel.valueBox()->setValue(0);
    panel.readButton()->click();
    ASSERT_TRUE(waitForResult(QStringLiteral("CV 3 = 42 (0x2a)"))) << panel.resultText().toStdString();
}

TEST_F(ProgrammingPanelTest, AnMm2ReadIsExplainedAndAnMm2WriteIsNotVerified) {
    ASSERT_TRUE(panel.chooseLocomotive(QStringLiteral("V 100 2023")));
    EXPECT_EQ(panel.protocolBox()->currentText(), QStringLiteral("MM2"));
    panel.readButton()->click();
    EXPECT_EQ(panel.resultText(),
              QStringLiteral("MM2 decoders cannot be read: the station can only write their CVs."));
    panel.cvBox()->setValue(5);
    panel.valueBox()->setValue(30);
    panel.writeButton()->click();
    ASSERT_TRUE(waitForResult(QStringLiteral("CV 5 written: 30. Not verified")))
        << panel.resultText().toStdString();
}

TEST_F(ProgrammingPanelTest, AnMfxCvIsWrittenAndReadWithItsIndex) {
    ASSERT_TRUE(panel.chooseLocomotive(QStringLiteral("BR 218 Ost")));
    EXPECT_EQ(panel.protocolBox()->currentText(), QStringLiteral("mfx SID"));
    panel.cvBox()->setValue(4);
    panel.indexBox()->setValue(0);
    panel.writeButton()->click();
    EXPECT_EQ(panel.resultText(), QStringLiteral("The mfx index must be between 1 and 63."))
        << "document 3.8";
    panel.indexBox()->setValue(2);
    panel.valueBox()->setValue(99);
    panel.writeButton()->click();
    ASSERT_TRUE(waitForResult(QStringLiteral("CV 4.2 written: 99"))) << panel.resultText().toStdString();
    panel.readButton()->click();
    ASSERT_TRUE(waitForResult(QStringLiteral("CV 4.2 = 99"))) << panel.resultText().toStdString();
}

// Not a check: with STELLWERK_SCREENSHOT_DIR set, saves the pictures of docs/screenshots/ (locomotives.png,
// programming.png) and, with STELLWERK_SCREENSHOT_DARK=1, the same pages in a dark palette.
TEST_F(ProgrammingPanelTest, SavesTheDocumentationScreenshotsWhenAsked) {
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    if (folder.isEmpty())
        GTEST_SKIP() << "set STELLWERK_SCREENSHOT_DIR to save the screenshots";
    const bool dark = qEnvironmentVariableIntValue("STELLWERK_SCREENSHOT_DARK") == 1;
    if (dark) {
        QPalette palette;
        palette.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
        palette.setColor(QPalette::WindowText, QColor(0xe0, 0xe0, 0xe0));
        palette.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
        palette.setColor(QPalette::AlternateBase, QColor(0x26, 0x26, 0x26));
        palette.setColor(QPalette::Text, QColor(0xe0, 0xe0, 0xe0));
        palette.setColor(QPalette::Button, QColor(0x35, 0x35, 0x35));
        palette.setColor(QPalette::ButtonText, QColor(0xe0, 0xe0, 0xe0));
        palette.setColor(QPalette::Highlight, QColor(0x2a, 0x6f, 0xb0));
        palette.setColor(QPalette::HighlightedText, Qt::white);
        palette.setColor(QPalette::Disabled, QPalette::Text, QColor(0x80, 0x80, 0x80));
        palette.setColor(QPalette::Disabled, QPalette::WindowText, QColor(0x80, 0x80, 0x80));
        palette.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(0x80, 0x80, 0x80));
        QApplication::setPalette(palette);
    }
    const QString suffix = dark ? QStringLiteral("-dark.png") : QStringLiteral(".png");
    LocomotivePictureBook pictures(&station.pictures()); // the embedded station's web server
    locomotives.setPictures(&pictures);
    locomotives.resize(1100, 640);
    ASSERT_TRUE(locomotives.selectLocomotive(QStringLiteral("ICE 3 Velaro")));
    locomotives.show();
    for (const char* icon : {"BR 218", "V 100", "ICE 3", "Koef III", "BR 01", "E 44", "BR 212", "Taurus",
                             "BR 89", "VT 98", "Re 460", "BR 103"})
        ASSERT_TRUE(QTest::qWaitFor([&] { return pictures.hasPicture(icon); }, AnswerMs)) << icon;
    QTest::qWait(100);
    EXPECT_TRUE(locomotives.grab().save(folder + QStringLiteral("/locomotives") + suffix));

    panel.resize(1100, 560);
    panel.show();
    ASSERT_TRUE(search());
    ASSERT_TRUE(panel.chooseLocomotive(QStringLiteral("BR 212 DB")));
    panel.cvBox()->setValue(3);
    panel.readButton()->click();
    ASSERT_TRUE(waitForResult(QStringLiteral("CV 3 =")));
    QTest::qWait(100);
    EXPECT_TRUE(panel.grab().save(folder + QStringLiteral("/programming") + suffix));
    if (dark)
        QApplication::setPalette(QPalette());
}
