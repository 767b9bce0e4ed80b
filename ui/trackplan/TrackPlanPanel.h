#pragma once

#include "cs2config/LayoutFolder.h"
#include "model/TrackLayout.h"
#include "trackgraph/TrackGraph.h"
#include "trackplan/BlockOutlines.h"
#include "trackplan/PageZoom.h"

#include <QList>
#include <QPointer>
#include <QWidget>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QLabel;
class QMenu;
class QTabWidget;
class QToolBar;

namespace stellwerk::automation {
class Automation;
}
namespace stellwerk::model {
class FeedbackContact;
class LayoutInUse;
class Railway;
} // namespace stellwerk::model

namespace stellwerk::ui {

class BlockLegend;
class BlockPopup;
class LayoutStateBanner;
class PlanAutomation;
class PlanGraph;
class ProblemBar;
class SetRoutes;
class TrackPageView;
struct TrackTileLook;

// The track plan: every page of the layout in use as a tab, with the railway's live turnout, signal,
// contact and route states while that layout is the station's, switching by click, and "Open layout..."
// and "Export layout..." asked of the layout in use. It shows the layout in use and its track graph
// (PlanGraph) and, when asked, draws the blocks, lists and marks the drawing's problems, and says what a
// block clicked leads to. While an automation runs on its layout it shades the blocks as the automation
// has them (trains, reserved ways, unknown occupants, faults) and places trains in blocks.
class TrackPlanPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TrackPlanPanel)

public:
    explicit TrackPlanPanel(QWidget* parent = nullptr);
    ~TrackPlanPanel() override;

    // The railway whose plan and states the panel shows (null: none; an opened folder stays shown).
    void setRailway(model::Railway* railway);
    // The layout it shows and asks to open and export folders (the program's, which the railway's binding
    // sets from the station's download; it must outlive the panel); until then one of its own, which only
    // opened folders fill.
    void setLayoutInUse(model::LayoutInUse* layout);
    model::LayoutInUse& layoutInUse() const { return *m_layoutInUse; }

    // Opens a CS2 configuration folder (the folder or its `config`) as the layout in use, as far as it is
    // there (the pages of gleisbilder/ when gleisbild.cs2 is missing, with a warning), or a single page
    // file; false and a problem shown when nothing can be read (the layout shown stays).
    bool openFolder(const QString& folder);
    // Asked before "Open layout..." shows its folder dialog; opening goes on only when it returns true
    // (the window asks about unsaved locomotive edits there).
    void setOpenGuard(std::function<bool()> mayOpen) { m_mayOpen = std::move(mayOpen); }
    bool mayOpen() const;
    // "Open layout..." and "Export layout..." on the plan's toolbar; LayoutFileActions gives them their work
    // and puts them into the File menu too.
    QAction* openAction() const { return m_open; }
    QAction* exportAction() const { return m_export; }
    // Shows the station's plan again after a folder was opened.
    void showStationPlan();
    // Writes the shown layout as a CS2 configuration folder; false and a problem shown on failure.
    bool exportTo(const QString& folder);

    QTabWidget* pageTabs() const { return m_tabs; }
    TrackPageView* pageView(int page) const;
    // The pages shown: the layout in use's (null: none).
    const model::TrackLayout* layout() const { return m_layout.get(); }
    // Says when the layout is stopped, halted or not reported; hidden while trains may run.
    LayoutStateBanner* layoutState() const { return m_layoutState; }
    // What a tile shows now (for tests and the screenshot tool).
    TrackTileLook lookOf(model::TileRef ref) const;
    QString toolTipOf(model::TileRef ref) const;
    // The zoom of the page in front (pixels per tile); each page keeps its own (PageZoom).
    int tileSize() const { return m_zoom->currentTile(); }
    void setTileSize(int pixels) { m_zoom->zoomCurrent(pixels); }
    void zoomIn();
    void zoomOut();
    // The drawn part of the page in front fills the window, and keeps filling it as the window changes.
    void fitToWindow() { m_zoom->fitCurrent(); }
    bool isFitted() const { return m_zoom->isCurrentFitted(); }
    // The problem shown in the banner; empty while it is hidden.
    QString problemText() const;
    // The red bar that shows it (folded, dismissed).
    ProblemBar* problemBar() const { return m_problem; }

    // The track graph of the layout shown, with the plan's tiles (null: no page).
    const PlanGraph* graph() const { return m_graph.get(); }
    // "Blocks" on the plan's toolbar (and in the View menu): outlines the blocks with their names, lists
    // the drawing's problems in the bar above the plan and marks their tiles; a click on a block's track
    // or contact then says its contacts and ways. Remembered (BlockViewSettings).
    QAction* blocksAction() const { return m_blocks; }
    bool showsBlocks() const;
    void setShowBlocks(bool shown);
    // The amber bar that lists the drawing's problems while the blocks are shown.
    ProblemBar* drawingProblemBar() const { return m_drawingProblems; }
    // The popup a click on a block opens.
    BlockPopup* blockPopup() const { return m_blockPopup; }
    // Opens the popup about the block on a tile (the first, where two tracks cross); false when the tile is
    // in no block or the blocks are not shown.
    bool showBlockAt(model::TileRef tile);
    // What a right click on a tile offers: its positions or occupant on a reported railway (TileMenu), while
    // the blocks are shown "Block ..." for each block it is in, and while an automation runs "Place a train
    // in ..." and "Remove ..." for each; false when there is nothing.
    bool fillTileMenu(QMenu& menu, model::TileRef tile);

    // The automation whose trains the plan shows and places (null: none; it may be deleted and replaced at
    // any time). Without one the plan looks as it always did.
    void setAutomation(automation::Automation* automation);
    // What the plan shows of it (the blocks' states as painted), and the legend above the plan.
    const PlanAutomation& planAutomation() const { return *m_planAutomation; }
    BlockLegend* blockLegend() const { return m_legend; }
    // Places a locomotive dropped on a tile in the tile's block, facing the end nearer `point` (the page
    // view's pixels); false (and the reason shown) when it was not placed.
    bool placeDropped(int page, int tile, QPoint point, std::uint32_t locId);

signals:
    // The pages shown were rebuilt (another railway, a reload, an opened folder).
    void layoutChanged();

protected:
    void changeEvent(QEvent* event) override;

private:
    void rebuild();
    void railwayLoaded();
    QString occupantName(const model::FeedbackContact& contact) const;
    // True while the pages shown are the station's, with the railway's live states.
    bool isLive() const;
    bool isReported() const;
    TrackTileLook lookOn(const model::TrackLayout& layout, model::TileRef ref) const;
    QString toolTipOn(const model::TrackLayout& layout, model::TileRef ref) const;
    void stateReportedChanged();
    void addPage(int index);
    void indexRoutes();
    void tilesChanged(const QList<model::TileRef>& tiles);
    void routeChanged(qint64 route);
    void updateSetRoutes();
    void tileClicked(int page, int tile);
    void showTileMenu(int page, int tile, QPoint where);
    void goToPage(std::int64_t pageId);
    QString accessoryName(std::int64_t id) const;
    QString routeName(std::int64_t id) const;
    void applyBlocks();
    void applyBlockStates();
    // What another program announced for a block on the bus, in words; empty when nothing.
    QString announcedStateOf(int block) const;
    QString memoryToolTip(std::int64_t route) const;
    void showBlock(model::TileRef tile, int block);
    QString graphToolTip(model::TileRef tile) const;
    QString automationToolTip(model::TileRef tile) const;
    BlockOutlines outlinesOf(int page, bool allBlocks) const;
    bool fillTrainEntries(QMenu& menu, model::TileRef tile, bool filled);
    void askToPlace(int block);
    trackgraph::End endNearer(int page, int block, QPoint point) const;
    void automationChanged();
    void showProblem(std::function<QString()> describe);
    static QString findingsText(const std::vector<cs2config::LayoutFinding>& findings);
    QString emptyPageText(int index) const;
    void updateActions();
    void updateIcons();
    void retranslate();

    bool showsFolder() const;
    void showOpenedFolder();

    QPointer<model::Railway> m_railway;
    model::LayoutInUse* m_layoutInUse = nullptr; // given ones outlive the panel
    // Shared with the page views, which keep their page alive whatever happens to the railway.
    std::shared_ptr<const model::TrackLayout> m_layout;
    bool m_live = false;
    std::map<std::int64_t, std::vector<model::TileRef>> m_routeTiles;
    std::vector<TrackPageView*> m_views;
    PageZoom* m_zoom = nullptr;
    std::unique_ptr<SetRoutes> m_setRoutes;
    std::function<bool()> m_mayOpen;
    std::shared_ptr<const PlanGraph> m_graph;

    QToolBar* m_toolBar = nullptr;
    QAction* m_open = nullptr;
    QAction* m_export = nullptr;
    QAction* m_station = nullptr;
    QAction* m_zoomIn = nullptr;
    QAction* m_zoomOut = nullptr;
    QAction* m_fit = nullptr;
    QAction* m_blocks = nullptr;
    QLabel* m_source = nullptr;
    ProblemBar* m_problem = nullptr;
    ProblemBar* m_drawingProblems = nullptr;
    BlockPopup* m_blockPopup = nullptr;
    PlanAutomation* m_planAutomation = nullptr;
    BlockLegend* m_legend = nullptr;
    LayoutStateBanner* m_layoutState = nullptr;
    QLabel* m_emptyText = nullptr;
    QTabWidget* m_tabs = nullptr;
};

} // namespace stellwerk::ui
