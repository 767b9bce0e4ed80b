// The Automatic panel on the demo's simulated CS2 (over loopback), with the Operation as the window holds
// it: a train placed through the Place dialog stands, manual, until Start; started, the panel follows its
// state; an unknown occupant on its way stops it with the fault's sentence in the table and below it; the
// schedule editor writes the schedule into the book on disk, and asks before dropping unsaved edits.
#include "automatic/AutomaticPanel.h"

#include "EmbeddedStationSupport.h"
#include "automatic/ScheduleDialog.h"
#include "binding/RailwayBinding.h"
#include "common/PlaceTrainDialog.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "operation/Operation.h"
#include "operation/TrainBookFile.h"
#include "shell/Translations.h"
#include "support/StationTestSupport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr std::uint32_t Br218 = 0x4001;

class AutomaticPanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        ASSERT_TRUE(server.start());
        operation::Operation::Options options;
        options.dataDir = data.path().toStdString();
        operation = std::make_unique<operation::Operation>(layout, options);
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, operation.get(),
                         &operation::Operation::setRailway);
        panel = std::make_unique<AutomaticPanel>();
        panel->setOperation(operation.get());
        QObject::connect(operation.get(), &operation::Operation::automationChanged, panel.get(),
                         &AutomaticPanel::setAutomation);
        station.connectTo(server.url());
        ASSERT_TRUE(test::waitForState(station, State::Ready));
        ASSERT_TRUE(QTest::qWaitFor([&] { return operation->automation() != nullptr; }, 5000));
        railways.railway()->go();
        ASSERT_TRUE(QTest::qWaitFor(
            [&] { return railways.railway()->power() == station::PowerState::Running; }, 5000));
        panel->resize(1000, 300);
        panel->show();
    }
    void TearDown() override {
        panel.reset();
        ASSERT_TRUE(translations.select(Language::English));
    }

    int blockNamed(const std::string& name) const {
        for (const trackgraph::Block& block : operation->automation()->dispatcher().graph().blocks())
            if (block.name == name)
                return block.id;
        ADD_FAILURE() << "no block " << name;
        return 0;
    }
    QString cell(std::uint32_t locId, int column) const {
        const int row = panel->rowOf(locId);
        return row < 0 ? QString() : panel->table()->item(row, column)->text();
    }
    QPushButton* button(const char* name) const {
        return panel->findChild<QPushButton*>(QLatin1String(name));
    }
    // BR 218 in Gleis 1 facing end b, through the dialog as a person does it.
    void placeThroughTheDialog() {
        button("placeTrainButton")->click();
        PlaceTrainDialog* dialog = panel->placeDialog();
        ASSERT_NE(dialog, nullptr);
        ASSERT_TRUE(dialog->isVisible());
        dialog->locomotiveBox()->setCurrentIndex(
            dialog->locomotiveBox()->findData(QVariant::fromValue(Br218)));
        dialog->blockBox()->setCurrentIndex(dialog->blockBox()->findText(QStringLiteral("Gleis 1")));
        dialog->setTowards(trackgraph::End::B);
        dialog->lengthBox()->setValue(260);
        dialog->accept();
    }

    QTemporaryDir data;
    Translations translations;
    test::TestStation server;
    connection::StationConnection station{support::withEmbeddedStation()};
    model::LayoutInUse layout;
    binding::RailwayBinding railways{station, &layout};
    std::unique_ptr<operation::Operation> operation;
    std::unique_ptr<AutomaticPanel> panel;
};

TEST_F(AutomaticPanelTest, APlacedTrainIsManualUntilStartedThenAFaultShowsItsSentence) {
    placeThroughTheDialog();
    ASSERT_GE(panel->rowOf(Br218), 0);
    EXPECT_EQ(cell(Br218, AutomaticPanel::TrainColumn), QStringLiteral("BR 218 Ost"));
    EXPECT_EQ(cell(Br218, AutomaticPanel::BlockColumn), QStringLiteral("Gleis 1"));
    EXPECT_EQ(cell(Br218, AutomaticPanel::StateColumn), QStringLiteral("manual"));
    EXPECT_EQ(operation->book().find(Br218)->lengthMm, 260);
    QTest::qWait(300);
    EXPECT_EQ(server.station().loco(Br218)->speed, 0);
    EXPECT_EQ(cell(Br218, AutomaticPanel::StateColumn), QStringLiteral("manual"));

    panel->selectTrain(Br218);
    ASSERT_TRUE(button("startTrainButton")->isEnabled());
    button("startTrainButton")->click();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return cell(Br218, AutomaticPanel::DestinationColumn) != QStringLiteral("–"); }, 5000))
        << cell(Br218, AutomaticPanel::StateColumn).toStdString();
    EXPECT_TRUE(cell(Br218, AutomaticPanel::StateColumn).startsWith(QStringLiteral("automatic, ")))
        << cell(Br218, AutomaticPanel::StateColumn).toStdString();
    EXPECT_TRUE(button("stopTrainButton")->isEnabled());

    // An unknown occupant in the block it runs to.
    const int destination = *operation->automation()->dispatcher().train(Br218)->destination;
    const trackgraph::ContactKey ghost =
        operation->automation()->dispatcher().graph().block(destination).contacts.front().contact;
    server.station().setContact(std::uint16_t(ghost.device), std::uint16_t(ghost.number), true);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return cell(Br218, AutomaticPanel::StateColumn).startsWith(QStringLiteral("fault: ")); }, 5000))
        << cell(Br218, AutomaticPanel::StateColumn).toStdString();
    EXPECT_TRUE(cell(Br218, AutomaticPanel::StateColumn).contains(QStringLiteral("unknown occupant")));
    EXPECT_TRUE(panel->faultLine()->isVisible());
    EXPECT_TRUE(panel->faultLine()->text().startsWith(QStringLiteral("Last fault: ")));
    EXPECT_TRUE(panel->faultLine()->text().contains(QStringLiteral("unknown occupant")));
    EXPECT_TRUE(QTest::qWaitFor([&] { return server.station().loco(Br218)->speed == 0; }, 3000));

    // Stop: manual, standing.
    button("stopTrainButton")->click();
    EXPECT_EQ(cell(Br218, AutomaticPanel::StateColumn), QStringLiteral("manual"));
}

TEST_F(AutomaticPanelTest, TheScheduleEditorWritesTheScheduleIntoTheBook) {
    ASSERT_FALSE(operation->place(Br218, blockNamed("Gleis 1"), trackgraph::End::B, 200, false));
    panel->selectTrain(Br218);
    EXPECT_EQ(cell(Br218, AutomaticPanel::ScheduleColumn), QStringLiteral("none: any free block"));
    button("scheduleButton")->click();
    ScheduleDialog* dialog = panel->scheduleDialog();
    ASSERT_NE(dialog, nullptr);
    dialog->addStop();
    dialog->addStop();
    dialog->setStop(0, "Gleis 2", 5);
    dialog->setStop(1, "Block 3", 2.5);
    dialog->loopBox()->setChecked(true);
    dialog->accept();

    const automation::Schedule& booked = operation->book().find(Br218)->schedule;
    ASSERT_EQ(booked.stops.size(), 2u);
    EXPECT_EQ(booked.stops[0].block, "Gleis 2");
    EXPECT_EQ(booked.stops[1].block, "Block 3");
    EXPECT_EQ(booked.stops[1].dwellMs, 2500);
    EXPECT_TRUE(booked.loop);
    EXPECT_EQ(cell(Br218, AutomaticPanel::ScheduleColumn),
              QStringLiteral("▸Gleis 2 (5 s) → Block 3 (2.5 s), loop"));
    const automation::Train* train = operation->automation()->dispatcher().train(Br218);
    ASSERT_TRUE(train->schedule.has_value());
    EXPECT_EQ(train->schedule->stops.size(), 2u);
    // On disk, as a restart reads it.
    operation::TrainBookFile file(operation->bookPath());
    std::string problem;
    const operation::TrainBook read = file.load(problem);
    EXPECT_EQ(problem, "");
    ASSERT_NE(read.find(Br218), nullptr);
    EXPECT_EQ(read.find(Br218)->schedule.stops.size(), 2u);
    EXPECT_EQ(read.find(Br218)->schedule.stops[1].block, "Block 3");
}

TEST_F(AutomaticPanelTest, UnsavedScheduleEditsAreAskedAboutOnEscape) {
    ASSERT_FALSE(operation->place(Br218, blockNamed("Gleis 1"), trackgraph::End::B, 200, false));
    panel->selectTrain(Br218);
    button("scheduleButton")->click();
    ScheduleDialog* dialog = panel->scheduleDialog();
    ASSERT_NE(dialog, nullptr);
    int asked = 0;
    QMessageBox::StandardButton answer = QMessageBox::Cancel;
    dialog->setUnsavedQuestion([&](QWidget*) {
        ++asked;
        return answer;
    });
    dialog->addStop();
    QTest::keyClick(dialog, Qt::Key_Escape);
    EXPECT_EQ(asked, 1);
    EXPECT_TRUE(dialog->isVisible()); // Cancel: still editing
    answer = QMessageBox::Discard;
    QTest::keyClick(dialog, Qt::Key_Escape);
    EXPECT_EQ(asked, 2);
    EXPECT_TRUE(QTest::qWaitFor([&] { return panel->scheduleDialog() == nullptr; }, 2000));
    EXPECT_TRUE(operation->book().find(Br218)->schedule.stops.empty());
}

TEST_F(AutomaticPanelTest, GermanNamesTheColumnsButtonsAndStates) {
    ASSERT_FALSE(operation->place(Br218, blockNamed("Gleis 1"), trackgraph::End::B, 200, false));
    ASSERT_TRUE(translations.select(Language::German));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_EQ(panel->table()->horizontalHeaderItem(AutomaticPanel::StateColumn)->text(),
              QStringLiteral("Zustand"));
    EXPECT_EQ(button("resumeButton")->text(), QStringLiteral("&Fortsetzen"));
    EXPECT_EQ(cell(Br218, AutomaticPanel::StateColumn), QStringLiteral("von Hand"));
    panel->selectTrain(Br218);
    button("placeTrainButton")->click();
    ASSERT_NE(panel->placeDialog(), nullptr);
    EXPECT_EQ(panel->placeDialog()->windowTitle(), QStringLiteral("Zug aufgleisen"));
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    if (!folder.isEmpty()) {
        panel->grab().save(folder + QStringLiteral("/automatic-panel-de.png"));
        panel->placeDialog()->grab().save(folder + QStringLiteral("/automatic-place-de.png"));
    }
    panel->placeDialog()->reject();
    button("scheduleButton")->click();
    ASSERT_NE(panel->scheduleDialog(), nullptr);
    panel->scheduleDialog()->addStop();
    panel->scheduleDialog()->addStop();
    panel->scheduleDialog()->setStop(1, "Abstellgleis", 12.5);
    EXPECT_EQ(panel->scheduleDialog()->stops()->horizontalHeaderItem(1)->text(), QStringLiteral("Haltezeit"));
    if (!folder.isEmpty())
        panel->scheduleDialog()->grab().save(folder + QStringLiteral("/automatic-schedule-de.png"));
    panel->scheduleDialog()->setUnsavedQuestion([](QWidget*) { return QMessageBox::Discard; });
    panel->scheduleDialog()->reject();
}

} // namespace
