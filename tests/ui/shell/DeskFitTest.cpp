// The first arrangement of the desk on a laptop (1366x768) and a full-HD screen (1920x1080), in English
// and German: every panel shows its content without a sideways scroll bar, in every state of a session
// (connected, after an edit, power off, station silent), no visible text is cut off, the keyboard shows
// its four columns, the plan is large enough for its names, and a throttle added below the others is
// scrolled into sight.

#include "keyboard/TurnoutKey.h"
#include "keyboard/TurnoutPanel.h"
#include "locomotives/LocomotiveForm.h"
#include "locomotives/LocomotivePanel.h"
#include "shell/Workspace.h"
#include "support/TrustTestSupport.h"
#include "throttle/ThrottlePanel.h"
#include "throttle/ThrottleWidget.h"
#include "trackplan/TileTag.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QDockWidget>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QStringList>
#include <QTabWidget>
#include <QTableView>
#include <QToolBar>
#include <QToolButton>
#include <QWidgetAction>
#include <tuple>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

constexpr quint32 Br218 = 0x4001; // locomotives of the demo layout
constexpr quint32 V100 = 0x18;
constexpr quint32 IceVelaro = 0x4002;

using Desk = std::tuple<QSize, Language>;

// The widget's class and name, and the nearest ancestor with a name where it has none.
QString nameOf(const QWidget* widget) {
    const QWidget* named = widget;
    while (named && named->objectName().isEmpty())
        named = named->parentWidget();
    return QStringLiteral("%1 \"%2\"")
        .arg(QString::fromLatin1(widget->metaObject()->className()), named ? named->objectName() : QString());
}

QString textOf(const QWidget* widget) {
    if (const auto* label = qobject_cast<const QLabel*>(widget))
        return label->text();
    if (const auto* button = qobject_cast<const QAbstractButton*>(widget))
        return button->text();
    if (const auto* combo = qobject_cast<const QComboBox*>(widget))
        return combo->currentText();
    return {};
}

// Whether the widget's own text is cut off: a label narrower (or, wrapping, shorter) than its text, a
// button or a choice narrower than its text and icon.
bool isCutOff(const QWidget* widget) {
    const QString text = textOf(widget);
    if (text.isEmpty() || widget->width() <= 0)
        return false;
    if (const auto* label = qobject_cast<const QLabel*>(widget)) {
        if (label->textFormat() == Qt::RichText || Qt::mightBeRichText(text))
            return false; // rich text lays itself out; the plain labels are what gets cut
        if (label->wordWrap())
            return label->heightForWidth(label->width()) > label->height() + 1;
        return label->minimumSizeHint().width() > label->width() + 1;
    }
    QString shown = text;
    shown.remove(QLatin1Char('&'));
    int needed = widget->fontMetrics().horizontalAdvance(shown) + 8;
    if (const auto* button = qobject_cast<const QAbstractButton*>(widget); button && !button->icon().isNull())
        needed += button->iconSize().width() + 4;
    if (qobject_cast<const QComboBox*>(widget))
        needed += 20; // the arrow
    return needed > widget->width();
}

bool isShown(const QWidget* widget) {
    return widget->isVisible() && !widget->visibleRegion().isEmpty();
}

QStringList sidewaysScrolling(const QWidget* dock) {
    QStringList found;
    // The overview's tables show all their columns (the bus monitor's long table may scroll).
    if (const QWidget* overview = dock->findChild<QWidget*>(QStringLiteral("layoutOverview")))
        for (const QTableView* table : overview->findChildren<QTableView*>())
            if (isShown(table) && table->horizontalScrollBar()->isVisible())
                found << QStringLiteral("%1 scrolls sideways (%2 of %3 px)")
                             .arg(nameOf(table))
                             .arg(table->viewport()->width())
                             .arg(table->horizontalHeader()->length());
    for (const QScrollArea* scroll : dock->findChildren<QScrollArea*>())
        if (isShown(scroll) && scroll->horizontalScrollBar()->isVisible())
            found << QStringLiteral("%1 scrolls sideways (%2 of %3 px)")
                         .arg(nameOf(scroll))
                         .arg(scroll->viewport()->width())
                         .arg(scroll->widget()->minimumSizeHint().width());
    return found;
}

class DeskFitTest : public test::DeskOnTestStation, public ::testing::WithParamInterface<Desk> {
protected:
    QSize deskSize() const override { return std::get<0>(GetParam()); }
    Language deskLanguage() const override { return std::get<1>(GetParam()); }

    void SetUp() override {
        DeskOnTestStation::SetUp();
        ASSERT_NE(window->throttlePanel()->addThrottle(Br218), nullptr);
        // Trains on two contacts, named as the demo names them: the contacts' widest rows.
        for (const quint16 contact : {1, 2}) {
            server.station().setContact(0, contact, true);
            ASSERT_TRUE(QTest::qWaitFor(
                [&] {
                    const model::FeedbackContact* c = railway()->contact(model::contactKey(0, contact));
                    return c && c->occupied();
                },
                CommandMs));
            railway()->reportOccupant(model::contactKey(0, contact), contact == 1 ? IceVelaro : Br218);
        }
        QTest::qWait(100);
    }

    // Every panel in front of its dock in turn: whose minimum width is more than its dock gives it, and
    // which dock scrolls sideways.
    QStringList widerThanTheirDocks(const QString& state) {
        QStringList found;
        for (QDockWidget* dock : window->workspace()->docks()) {
            QWidget* panel = Workspace::panelOf(dock);
            window->workspace()->showPanel(panel);
            QTest::qWait(60);
            const auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
            if (panel->minimumSizeHint().width() > scroll->viewport()->width())
                found << QStringLiteral("%1: %2 needs %3 px, its dock gives %4")
                             .arg(state, panel->objectName())
                             .arg(panel->minimumSizeHint().width())
                             .arg(scroll->viewport()->width());
            for (const QString& problem : sidewaysScrolling(dock))
                found << state + QStringLiteral(": ") + problem;
        }
        return found;
    }

    // Every panel in front of its dock in turn: what needs a sideways scroll bar, what text is cut off.
    QStringList problems() {
        QStringList found;
        for (QDockWidget* dock : window->workspace()->docks()) {
            QWidget* panel = Workspace::panelOf(dock);
            window->workspace()->showPanel(panel);
            QTest::qWait(60);
            found << sidewaysScrolling(dock);
            for (const QWidget* widget : panel->findChildren<QWidget*>())
                if (isShown(widget) && isCutOff(widget))
                    found << QStringLiteral("%1 in %2 cuts off \"%3\" (%4 px wide)")
                                 .arg(nameOf(widget), panel->objectName(), textOf(widget))
                                 .arg(widget->width());
            for (const TurnoutKey* key : panel->findChildren<TurnoutKey*>())
                if (isShown(key) && key->isTextElided())
                    found
                        << QStringLiteral("key %1 shortens \"%2\"").arg(key->address()).arg(key->face().name);
        }
        return found;
    }
};

} // namespace

TEST_P(DeskFitTest, NoPanelScrollsSidewaysAndNoTextIsCutOff) {
    const QStringList found = problems();
    EXPECT_TRUE(found.isEmpty()) << found.join(QLatin1Char('\n')).toStdString();
}

// Every page of the demo's plan, fitted into the room the first arrangement leaves it, is large enough for
// the names of its contacts, turnouts, signals and routes, in a readable size; siblings, names that differ
// only in their last word ("Block 1" … "Block 4", "Einfahrt 1" and "Einfahrt 2"), still differ where they
// are shortened.
TEST_P(DeskFitTest, ThePlanShowsItsNamesReadablyAndSiblingsDistinct) {
    TrackPlanPanel* plan = window->trackPlan();
    ASSERT_GE(plan->pageTabs()->count(), 3);
    for (int page = 0; page < plan->pageTabs()->count(); ++page) {
        plan->pageTabs()->setCurrentIndex(page);
        QTest::qWait(30);
        const TrackPageView* view = plan->pageView(page);
        const std::string pageName = plan->pageTabs()->tabText(page).toStdString();
        ASSERT_TRUE(plan->isFitted());
        ASSERT_GE(view->tileSize(), TileTag::MinimumTile)
            << "page " << pageName << " is drawn too small for names";
        QHash<QString, QString> fileNameOf; // family and shown name → the name in the file
        const model::LayoutPage& tiles = plan->layout()->pages().at(std::size_t(page));
        for (int tile = 0; tile < int(tiles.tiles.size()); ++tile) {
            const TileTag tag = view->tagOf(tile);
            if (!tag.shown())
                continue;
            EXPECT_GE(tag.font().pixelSize(), TileTag::ReadablePixels);
            const QString file = tiles.tiles.at(std::size_t(tile)).text.trimmed();
            const QString shown = file.section(QLatin1Char(' '), 0, -2) + QStringLiteral(" | ") + tag.text();
            EXPECT_EQ(fileNameOf.value(shown, file), file)
                << "on " << pageName << " \"" << file.toStdString() << "\" and \""
                << fileNameOf.value(shown).toStdString() << "\" both read \"" << tag.text().toStdString()
                << "\"";
            fileNameOf.insert(shown, file);
        }
        EXPECT_GE(fileNameOf.size(), 3) << "page " << pageName << " shows its names";
    }
}

// No panel grows wider than its dock from its own text, in any state a session goes through: connected,
// after an edit (the Locomotives panel's "12 locomotives, changed and not saved"), with the track power
// off, and with the station silent (the keyboard's "… · positions not reported"). A panel's minimum width
// fits its dock, and no dock scrolls sideways.
TEST_P(DeskFitTest, NoPanelGrowsWiderThanItsDockInAnyState) {
    QStringList found = widerThanTheirDocks(QStringLiteral("connected"));
    LocomotivePanel* locomotives = window->locomotivePanel();
    ASSERT_TRUE(locomotives->selectLocomotive(QStringLiteral("V 100 2023")));
    locomotives->form()->nameEdit()->setText(QStringLiteral("V 100 2023 Museumslok"));
    ASSERT_TRUE(locomotives->applyForm()) << locomotives->messageText().toStdString();
    ASSERT_TRUE(locomotives->hasUnsavedEdits());
    found << widerThanTheirDocks(QStringLiteral("after an edit"));
    railway()->stop();
    ASSERT_TRUE(powerBecomes(station::PowerState::Stopped));
    found << widerThanTheirDocks(QStringLiteral("power off"));
    server.stop();
    ASSERT_TRUE(reported(false));
    found << widerThanTheirDocks(QStringLiteral("station silent"));
    EXPECT_TRUE(found.isEmpty()) << found.join(QLatin1Char('\n')).toStdString();
}

TEST_P(DeskFitTest, ToolbarsShowEveryButtonWithItsDrawing) {
    const QList<QToolBar*> bars = window->findChildren<QToolBar*>();
    ASSERT_GE(bars.size(), 2) << "the window's and the plan's";
    for (const QToolBar* bar : bars) {
        const auto* more = bar->findChild<QToolButton*>(QStringLiteral("qt_toolbar_ext_button"));
        EXPECT_TRUE(!more || !more->isVisible()) << nameOf(bar).toStdString() << " hides buttons behind »";
        for (QAction* action : bar->actions()) {
            const auto* button = qobject_cast<QToolButton*>(bar->widgetForAction(action));
            if (!button || !action->isVisible() || qobject_cast<QWidgetAction*>(action))
                continue; // separators, and widgets of their own such as the STOP key
            EXPECT_FALSE(action->icon().isNull()) << action->text().toStdString() << " has no drawing";
            if (button->toolButtonStyle() == Qt::ToolButtonIconOnly) {
                EXPECT_TRUE(action->toolTip().contains(action->text())) << "a drawing alone names itself";
            }
        }
    }
}

TEST_P(DeskFitTest, TheKeyboardShowsItsFourColumns) {
    const QList<TurnoutKey*> keys = window->turnoutPanel()->keys();
    ASSERT_EQ(keys.size(), TurnoutPanel::KeysPerPage);
    for (int column = 0; column < 4; ++column) {
        const TurnoutKey* key = keys.at(column);
        const QRect shown = key->visibleRegion().boundingRect();
        EXPECT_EQ(shown.width(), key->width()) << "key " << key->address() << " is cut off at the side";
    }
    EXPECT_LT(keys.at(0)->mapTo(window.get(), QPoint()).y(), keys.at(4)->mapTo(window.get(), QPoint()).y())
        << "the fifth key starts the second row";
}

TEST_P(DeskFitTest, AnAddedThrottleIsScrolledIntoSight) {
    ThrottleWidget* second = window->throttlePanel()->addThrottle(V100);
    ASSERT_NE(second, nullptr);
    ASSERT_TRUE(QTest::qWaitFor([&] { return isShown(second); }, 2000));
    const QRect shown = second->visibleRegion().boundingRect();
    EXPECT_EQ(shown.width(), second->width()) << "the new throttle is cut off at the side";
    const ThrottleWidget* first = window->throttlePanel()->throttles().first();
    const bool wide = deskSize().width() >= 1800;
    EXPECT_EQ(first->y() == second->y(), wide) << "side by side on a wide screen, stacked on a laptop";
}

TEST_P(DeskFitTest, ThrottlesAndGaugesWrapAgainWhenTheirPanelGetsNarrower) {
    ASSERT_NE(window->throttlePanel()->addThrottle(V100), nullptr);
    QDockWidget* side = window->workspace()->dockOf(window->throttlePanel());
    window->resizeDocks({side}, {window->throttlePanel()->widthFor(2)}, Qt::Horizontal);
    QTest::qWait(60);
    window->resizeDocks({side}, {window->throttlePanel()->widthFor(1)}, Qt::Horizontal);
    QTest::qWait(60);
    for (QWidget* panel :
         {static_cast<QWidget*>(window->throttlePanel()), window->workspace()->panel("statusPanel")}) {
        window->workspace()->showPanel(panel);
        QTest::qWait(60);
        const QStringList found = sidewaysScrolling(side);
        EXPECT_TRUE(found.isEmpty()) << found.join(QLatin1Char('\n')).toStdString();
    }
}

INSTANTIATE_TEST_SUITE_P(, DeskFitTest,
                         ::testing::Combine(::testing::Values(QSize(1366, 768), QSize(1920, 1080)),
                                            ::testing::Values(Language::English, Language::German)),
                         [](const ::testing::TestParamInfo<Desk>& info) {
                             const QSize size = std::get<0>(info.param);
                             const bool german = std::get<1>(info.param) == Language::German;
                             return std::to_string(size.width()) + "x" + std::to_string(size.height()) +
                                    (german ? "German" : "English");
                         });
