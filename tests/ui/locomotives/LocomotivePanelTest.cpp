// The Locomotives page on the embedded simulated CS2: edit, refuse, add and save lokomotive.cs2.

#include "locomotives/LocomotivePanel.h"

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "locomotives/LocomotiveFileModel.h"
#include "locomotives/LocomotiveForm.h"
#include "model/Railway.h"
#include "model/Z21Addresses.h"
#include "shell/Translations.h"
#include "support/StationTestSupport.h"

#include <QComboBox>
#include <QFile>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr quint32 V100 = 0x18; // V 100 2023, MM2 address 24

QStringList linesOf(const QByteArray& bytes) {
    return QString::fromUtf8(bytes).split(QLatin1Char('\n'));
}

class LocomotivePanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &panel,
                         &LocomotivePanel::setRailway);
        station.connectToSimulator();
        ASSERT_TRUE(test::waitForState(station, State::Ready));
        ASSERT_NE(railways.railway(), nullptr);
        ASSERT_NE(railways.railway()->locomotiveFile(), nullptr);
    }
    model::Railway& railway() { return *railways.railway(); }
    QByteArray stationFile() const {
        return QByteArray::fromStdString(
            cs2config::LocomotiveEditor(*railways.railway()->locomotiveFile()).bytes());
    }

    Translations translations;
    connection::StationConnection station{support::withEmbeddedStation()};
    binding::RailwayBinding railways{station};
    LocomotivePanel panel;
};

} // namespace

TEST_F(LocomotivePanelTest, ListsTheStationsLocomotivesWithAddressDecoderAndFunctions) {
    const LocomotiveFileModel& list = *panel.model();
    ASSERT_EQ(list.rowCount(), 12);
    ASSERT_TRUE(panel.selectLocomotive(QStringLiteral("V 100 2023")));
    const int row = panel.table()->selectionModel()->selectedRows().value(0).row();
    EXPECT_EQ(list.index(row, LocomotiveFileModel::Address).data().toString(), QStringLiteral("MM2 24"));
    EXPECT_EQ(list.index(row, LocomotiveFileModel::Decoder).data().toString(),
              QStringLiteral("MM2 (programmable)"));
    EXPECT_EQ(list.index(row, LocomotiveFileModel::Functions).data().toString(), QStringLiteral("5"));
    EXPECT_EQ(panel.form()->nameEdit()->text(), QStringLiteral("V 100 2023"));
    EXPECT_EQ(panel.form()->addressBox()->value(), 24);
}

TEST_F(LocomotivePanelTest, TheFunctionsShowWhatTheirIconNumberIsWithItsDrawing) {
    ASSERT_TRUE(panel.selectLocomotive(QStringLiteral("BR 218 Ost")));
    LocomotiveForm* form = panel.form();
    ASSERT_EQ(form->iconBox(0)->value(), 1) << "the demo's F0 is the CS2's icon 1, light";
    EXPECT_EQ(form->pictureText(0), QStringLiteral("Light")) << "shown as soon as the locomotive is chosen";
    EXPECT_TRUE(form->showsPicture(0));
    form->iconBox(3)->setValue(1);
    EXPECT_EQ(form->pictureText(3), QStringLiteral("Light"));
    EXPECT_TRUE(form->showsPicture(3));
    form->iconBox(3)->setValue(0); // none of our drawings
    EXPECT_EQ(form->pictureText(3), QStringLiteral("Function"));
    EXPECT_FALSE(form->showsPicture(3)) << "a number we have no drawing for shows none, not a wrong one";
}

TEST_F(LocomotivePanelTest, ARenameIsSavedToTheChosenFolderAndEverythingElseStays) {
    const QByteArray before = stationFile();
    ASSERT_TRUE(panel.selectLocomotive(QStringLiteral("V 100 2023")));
    panel.form()->nameEdit()->setText(QStringLiteral("V 100 Museum"));
    ASSERT_TRUE(panel.applyForm()) << panel.messageText().toStdString();
    EXPECT_EQ(railway().locomotive(V100)->name(), QStringLiteral("V 100 Museum"))
        << "the railway follows the edit";

    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    ASSERT_TRUE(panel.saveTo(folder.path())) << panel.messageText().toStdString();
    EXPECT_TRUE(panel.messageText().startsWith(QStringLiteral("Saved to")));
    QFile saved(folder.filePath(QStringLiteral("config/lokomotive.cs2")));
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    const QStringList old = linesOf(before), now = linesOf(saved.readAll());
    ASSERT_EQ(now.size(), old.size());
    QStringList changed;
    for (int i = 0; i < now.size(); ++i)
        if (now[i] != old[i])
            changed << now[i];
    EXPECT_EQ(changed, QStringList{QStringLiteral(" .name=V 100 Museum")});
}

TEST_F(LocomotivePanelTest, AnAddressOutsideTheDecodersRangeIsRefusedWithTheReason) {
    const QByteArray before = stationFile();
    ASSERT_TRUE(panel.selectLocomotive(QStringLiteral("Köf III"))); // MM2 with DIL switches
    panel.form()->addressBox()->setValue(200);
    EXPECT_FALSE(panel.applyForm());
    EXPECT_EQ(panel.messageText(), QStringLiteral("The address must be between 1 and 80 for this decoder."));
    EXPECT_FALSE(panel.editor().modified());
    EXPECT_EQ(stationFile(), before) << "nothing changed";
    EXPECT_EQ(panel.form()->addressBox()->value(), 200) << "the typed value stays to be corrected";
}

TEST_F(LocomotivePanelTest, AnAddressInUseNamesTheOtherLocomotive) {
    ASSERT_TRUE(panel.selectLocomotive(QStringLiteral("BR 212 DB"))); // DCC 3
    panel.form()->addressBox()->setValue(16);                         // Taurus 1016 ÖBB
    EXPECT_FALSE(panel.applyForm());
    EXPECT_EQ(panel.messageText(), QStringLiteral("'Taurus 1016 ÖBB' already uses this address."));
}

TEST_F(LocomotivePanelTest, ANewDccLocomotiveWithATimedFunctionJoinsTheRailway) {
    panel.startNewLocomotive();
    panel.form()->nameEdit()->setText(QStringLiteral("BR 80 Werklok"));
    panel.form()->decoderBox()->setCurrentIndex(
        panel.form()->decoderBox()->findData(int(cs2config::LocomotiveDecoder::Dcc)));
    panel.form()->addressBox()->setValue(80);
    panel.form()->iconBox(2)->setValue(7);
    panel.form()->triggerBox(2)->setCurrentIndex(2); // timed
    panel.form()->durationBox(2)->setValue(4);
    ASSERT_TRUE(panel.applyForm()) << panel.messageText().toStdString();
    EXPECT_EQ(panel.model()->rowCount(), 13);
    const model::Locomotive* added = railway().locomotive(0xC050);
    ASSERT_NE(added, nullptr);
    EXPECT_EQ(added->name(), QStringLiteral("BR 80 Werklok"));
    ASSERT_NE(added->function(2), nullptr);
    EXPECT_EQ(added->function(2)->trigger, cs2config::FunctionTrigger::Timed);
    const cs2config::Locomotive& record = panel.editor().locomotives().back();
    EXPECT_EQ(record.function(2)->duration, 4);
    EXPECT_EQ(record.function(2)->icon, 7);
}

TEST_F(LocomotivePanelTest, ADeletedLocomotiveLeavesTheListAndTheRailway) {
    ASSERT_TRUE(panel.selectLocomotive(QStringLiteral("V 100 2023")));
    ASSERT_TRUE(panel.removeSelected());
    EXPECT_EQ(panel.model()->rowCount(), 11);
    EXPECT_EQ(railway().locomotive(V100), nullptr);
}

TEST_F(LocomotivePanelTest, EnterInTheNameFieldAppliesTheEdit) {
    ASSERT_TRUE(panel.selectLocomotive(QStringLiteral("E 44 043")));
    panel.form()->nameEdit()->setText(QStringLiteral("E 44 Bw Freilassing"));
    QTest::keyClick(panel.form()->nameEdit(), Qt::Key_Return);
    EXPECT_EQ(railway().locomotive(0x2C)->name(), QStringLiteral("E 44 Bw Freilassing"));
    EXPECT_TRUE(panel.editor().modified());
}

TEST(LocomotivePanelWithoutStation, SaysSoAndOffersNothingToSave) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    LocomotivePanel panel;
    EXPECT_EQ(panel.model()->rowCount(), 0);
    EXPECT_FALSE(panel.findChild<QPushButton*>(QStringLiteral("saveLocomotives"))->isEnabled());
    EXPECT_FALSE(panel.findChild<QPushButton*>(QStringLiteral("newLocomotive"))->isEnabled());
    EXPECT_FALSE(panel.form()->isEnabled());
    EXPECT_FALSE(panel.applyForm());
    const QList<QLabel*> labels = panel.findChildren<QLabel*>();
    EXPECT_TRUE(std::any_of(labels.begin(), labels.end(), [](const QLabel* label) {
        return label->text() == QStringLiteral("No station connected.");
    }));
}

// Issue 35: the Z21 address column with the phone servers' book, saved in the settings at each change.
class LocomotiveZ21AddressTest : public LocomotivePanelTest {
protected:
    void SetUp() override {
        LocomotivePanelTest::SetUp();
        panel.setZ21Addresses(&book, [this] {
            QSettings settings(settingsFile(), QSettings::IniFormat);
            book.save(settings);
        });
    }
    QString settingsFile() const { return dir.filePath(QStringLiteral("stellwerk.ini")); }
    // The Z21 address of `locomotive` as the settings hold it now.
    std::optional<std::uint16_t> saved(quint32 locId) const {
        QSettings settings(settingsFile(), QSettings::IniFormat);
        return model::Z21Addresses::load(settings).addressOf(locId);
    }
    QModelIndex z21Cell(const QString& name) {
        EXPECT_TRUE(panel.selectLocomotive(name));
        const int row = panel.table()->selectionModel()->selectedRows().value(0).row();
        return panel.model()->index(row, LocomotiveFileModel::Z21Address);
    }

    QTemporaryDir dir;
    model::Z21Addresses book;
};

// In a dock as narrow as the window's at 1366x768, with the Z21 column: every name is shown whole (the list
// scrolls sideways instead of cutting names short).
TEST_F(LocomotiveZ21AddressTest, InANarrowDockEveryNameIsShownWhole) {
    panel.resize(450, 600);
    panel.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    QTableView* table = panel.table();
    ASSERT_FALSE(table->isColumnHidden(LocomotiveFileModel::Z21Address));
    for (int row = 0; row < panel.model()->rowCount(); ++row) {
        const QString name = panel.model()->index(row, LocomotiveFileModel::Name).data().toString();
        EXPECT_GE(table->columnWidth(LocomotiveFileModel::Name), table->fontMetrics().horizontalAdvance(name))
            << name.toStdString() << " is cut short";
    }
}

TEST_F(LocomotiveZ21AddressTest, AnMmLocomotivesZ21AddressIsEditedInTheListAndSavedAtOnce) {
    EXPECT_FALSE(panel.table()->isColumnHidden(LocomotiveFileModel::Z21Address));
    const QModelIndex cell = z21Cell(QStringLiteral("V 100 2023"));
    EXPECT_EQ(cell.data().toString(), QStringLiteral("24")) << "an MM locomotive starts on its MM address";
    EXPECT_EQ(saved(V100), 24) << "the addresses given are kept with the settings";
    ASSERT_TRUE(panel.model()->flags(cell) & Qt::ItemIsEditable);

    panel.show();
    panel.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&panel));
    panel.table()->setFocus();
    QTest::keyClick(panel.table(), Qt::Key_F2); // F2 edits the selected locomotive's Z21 address
    auto* editor = panel.table()->viewport()->findChild<QSpinBox*>();
    ASSERT_NE(editor, nullptr);
    EXPECT_EQ(editor->value(), 24) << "the editor starts at the address shown";
    editor->setValue(512);
    QTest::keyClick(editor, Qt::Key_Return); // the delegate commits on the next turn of the event loop
    ASSERT_TRUE(QTest::qWaitFor([&] { return book.addressOf(V100) == 512; }, 3000));

    EXPECT_EQ(cell.data().toString(), QStringLiteral("512"));
    EXPECT_EQ(book.addressOf(V100), 512);
    EXPECT_EQ(saved(V100), 512);
    EXPECT_EQ(panel.messageText(), QStringLiteral("'V 100 2023' has Z21 address 512 now."));
}

TEST_F(LocomotiveZ21AddressTest, ATakenOrImpossibleZ21AddressIsRefusedWithASentence) {
    const QModelIndex cell = z21Cell(QStringLiteral("V 100 2023"));
    EXPECT_FALSE(panel.model()->setData(cell, 3)); // BR 212 DB is DCC 3
    EXPECT_EQ(panel.messageText(),
              QStringLiteral("'BR 212 DB' already has Z21 address 3; 'V 100 2023' keeps 24."));
    EXPECT_FALSE(panel.model()->setData(cell, 10000));
    EXPECT_EQ(panel.messageText(),
              QStringLiteral("A Z21 address is a number from 1 to 9999; 'V 100 2023' keeps 24."));
    EXPECT_FALSE(panel.model()->setData(cell, 0));
    EXPECT_EQ(cell.data().toString(), QStringLiteral("24"));
    EXPECT_EQ(saved(V100), 24) << "nothing refused is saved";
}

TEST_F(LocomotiveZ21AddressTest, ADccLocomotiveShowsItsOwnAddressAndCannotBeChanged) {
    const QModelIndex cell = z21Cell(QStringLiteral("BR 212 DB"));
    EXPECT_EQ(cell.data().toString(), QStringLiteral("3"));
    EXPECT_FALSE(panel.model()->flags(cell) & Qt::ItemIsEditable);
    EXPECT_FALSE(panel.model()->setData(cell, 77));
    EXPECT_EQ(cell.data().toString(), QStringLiteral("3"));
}

TEST_F(LocomotivePanelTest, WithoutPhoneServersTheZ21ColumnIsHidden) {
    EXPECT_TRUE(panel.table()->isColumnHidden(LocomotiveFileModel::Z21Address));
}
