// Unsaved locomotive edits are never lost without asking: quitting, Station → Connect… and opening another
// layout ask "Save / Discard / Cancel" first, and Cancel keeps everything as it was.

#include "locomotives/LocomotiveForm.h"
#include "locomotives/LocomotivePanel.h"
#include "support/TrustTestSupport.h"
#include "trackplan/TrackPlanPanel.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr quint32 EditedV100 = 0x18;
const QString Renamed = QStringLiteral("V 100 Museum");

// Answers whatever opens modally next, one answer per window, and notes what was asked.
class ModalAnswers : public QObject {
public:
    using Answer = std::function<void(QWidget*)>;
    explicit ModalAnswers(QList<Answer> answers) : m_answers(std::move(answers)) {
        connect(&m_poll, &QTimer::timeout, this, &ModalAnswers::poll);
        m_poll.start(20);
    }
    QStringList asked;

private:
    void poll() {
        QWidget* modal = QApplication::activeModalWidget();
        if (!modal || modal == m_last)
            return;
        m_last = modal;
        asked << modal->metaObject()->className();
        if (m_answers.isEmpty()) {
            modal->close(); // not expected: never hang
            return;
        }
        m_answers.takeFirst()(modal);
    }

    QList<Answer> m_answers;
    QTimer m_poll;
    QPointer<QWidget> m_last;
};

ModalAnswers::Answer boxAnswer(QMessageBox::StandardButton button, QString* text = nullptr) {
    return [button, text](QWidget* modal) {
        auto* box = qobject_cast<QMessageBox*>(modal);
        ASSERT_NE(box, nullptr) << modal->metaObject()->className();
        if (text)
            *text = box->text();
        box->button(button)->click();
    };
}

class UnsavedLocomotivesTest : public test::DeskOnTestStation {
protected:
    void SetUp() override {
        DeskOnTestStation::SetUp();
        LocomotivePanel* panel = window->locomotivePanel();
        ASSERT_TRUE(panel->selectLocomotive(QStringLiteral("V 100 2023")));
        panel->form()->nameEdit()->setText(Renamed);
        ASSERT_TRUE(panel->applyForm()) << panel->messageText().toStdString();
        ASSERT_TRUE(panel->hasUnsavedEdits());
    }
    QString v100Name() const { return railway()->locomotive(EditedV100)->name(); }
};

} // namespace

TEST_F(UnsavedLocomotivesTest, QuittingAsksAndCancelKeepsTheWindowAndTheEdits) {
    QString question;
    ModalAnswers answers({boxAnswer(QMessageBox::Cancel, &question)});
    EXPECT_FALSE(window->close());
    EXPECT_TRUE(window->isVisible());
    EXPECT_TRUE(question.contains(QStringLiteral("not saved"))) << question.toStdString();
    EXPECT_TRUE(window->locomotivePanel()->hasUnsavedEdits());
    EXPECT_EQ(v100Name(), Renamed);
}

TEST_F(UnsavedLocomotivesTest, QuittingWithDiscardClosesAndTheStationsListIsBack) {
    ModalAnswers answers({boxAnswer(QMessageBox::Discard)});
    EXPECT_TRUE(window->close());
    EXPECT_FALSE(window->locomotivePanel()->hasUnsavedEdits());
    EXPECT_EQ(v100Name(), QStringLiteral("V 100 2023"));
}

TEST_F(UnsavedLocomotivesTest, QuittingWithSaveWritesTheFileIntoTheChosenFolderFirst) {
    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    ModalAnswers answers({boxAnswer(QMessageBox::Save), [&folder](QWidget* modal) {
                              auto* files = qobject_cast<QFileDialog*>(modal);
                              ASSERT_NE(files, nullptr) << modal->metaObject()->className();
                              files->setDirectory(folder.path());
                              static_cast<QDialog*>(files)->accept(); // QFileDialog::accept, virtually
                          }});
    EXPECT_TRUE(window->close());
    EXPECT_TRUE(window->locomotivePanel()->messageText().contains(folder.path()))
        << window->locomotivePanel()->messageText().toStdString();
    QFile saved(folder.filePath(QStringLiteral("config/lokomotive.cs2")));
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly)) << answers.asked.join(QLatin1Char(' ')).toStdString();
    EXPECT_TRUE(saved.readAll().contains(" .name=V 100 Museum\n"));
}

TEST_F(UnsavedLocomotivesTest, ConnectingAgainAsksAndCancelKeepsTheSession) {
    const model::Railway* before = railway();
    ModalAnswers answers(
        {[](QWidget* modal) { static_cast<QDialog*>(modal)->accept(); }, boxAnswer(QMessageBox::Cancel)});
    window->showConnectDialog();
    EXPECT_EQ(answers.asked,
              QStringList({QStringLiteral("stellwerk::ui::ConnectDialog"), QStringLiteral("QMessageBox")}));
    QTest::qWait(200);
    EXPECT_EQ(railway(), before) << "no new session";
    EXPECT_EQ(connection.state(), State::Ready);
    EXPECT_EQ(v100Name(), Renamed);
}

TEST_F(UnsavedLocomotivesTest, OpeningAnotherLayoutAsksAndCancelOpensNoFolderDialog) {
    QAction* open = nullptr;
    for (QAction* action : window->trackPlan()->findChild<QToolBar*>()->actions())
        if (action->text() == QStringLiteral("Open layout..."))
            open = action;
    ASSERT_NE(open, nullptr);
    ModalAnswers answers({boxAnswer(QMessageBox::Cancel)});
    open->trigger();
    EXPECT_EQ(answers.asked, QStringList{QStringLiteral("QMessageBox")});
    EXPECT_TRUE(window->locomotivePanel()->hasUnsavedEdits());
}
