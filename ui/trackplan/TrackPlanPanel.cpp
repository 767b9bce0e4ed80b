#include "trackplan/TrackPlanPanel.h"

#include "common/LayoutStateBanner.h"
#include "common/NotReported.h"
#include "common/ProblemBar.h"
#include "common/ToolIcons.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "trackgraph/TrackGraph.h"
#include "trackplan/AnnouncedStateText.h"
#include "trackplan/BlockDescription.h"
#include "trackplan/BlockLegend.h"
#include "trackplan/BlockOutlines.h"
#include "trackplan/BlockPopup.h"
#include "trackplan/BlockViewSettings.h"
#include "trackplan/GraphProblemText.h"
#include "trackplan/PageZoom.h"
#include "trackplan/PlanAutomation.h"
#include "trackplan/PlanGraph.h"
#include "trackplan/SetRoutes.h"
#include "trackplan/TileMenu.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackTileInfo.h"
#include "trackplan/TrackTileLook.h"

#include <QAction>
#include <QEvent>
#include <QLabel>
#include <QMenu>
#include <QScrollArea>
#include <QScrollBar>
#include <QTabWidget>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <filesystem>

namespace stellwerk::ui {

TrackPlanPanel::TrackPlanPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("trackPlanPanel"));
    m_setRoutes = std::make_unique<SetRoutes>();
    auto* layout = new QVBoxLayout(this);
    m_toolBar = new QToolBar(this);
    m_open = m_toolBar->addAction(QString()); // LayoutFileActions asks for the folder
    m_open->setObjectName(QStringLiteral("openLayoutAction"));
    m_station = m_toolBar->addAction(QString(), this, &TrackPlanPanel::showStationPlan);
    m_export = m_toolBar->addAction(QString());
    m_export->setObjectName(QStringLiteral("exportLayoutAction"));
    m_toolBar->addSeparator();
    m_zoomOut = m_toolBar->addAction(QString(), this, &TrackPlanPanel::zoomOut);
    m_zoomIn = m_toolBar->addAction(QString(), this, &TrackPlanPanel::zoomIn);
    m_fit = m_toolBar->addAction(QString(), this, &TrackPlanPanel::fitToWindow);
    m_zoomIn->setShortcuts({QKeySequence::ZoomIn, QKeySequence(Qt::CTRL | Qt::Key_Equal)});
    m_zoomOut->setShortcut(QKeySequence::ZoomOut);
    m_fit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    for (QAction* action : {m_zoomIn, m_zoomOut, m_fit})
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_toolBar->addSeparator();
    m_blocks = m_toolBar->addAction(QString());
    m_blocks->setObjectName(QStringLiteral("showBlocksAction"));
    m_blocks->setCheckable(true);
    m_blocks->setChecked(BlockViewSettings::shown());
    connect(m_blocks, &QAction::toggled, this, [this](bool shown) {
        BlockViewSettings::setShown(shown);
        applyBlocks();
    });
    // Files and the station's plan say what they do; the zoom keys are known by their drawings.
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->setIconSize(QSize(20, 20));
    for (QAction* action : {m_zoomIn, m_zoomOut, m_fit})
        static_cast<QToolButton*>(m_toolBar->widgetForAction(action))
            ->setToolButtonStyle(Qt::ToolButtonIconOnly);
    updateIcons();
    layout->addWidget(m_toolBar);

    m_problem = new ProblemBar(this);
    m_problem->setObjectName(QStringLiteral("trackPlanProblem"));
    layout->addWidget(m_problem);
    m_drawingProblems = new ProblemBar(this);
    m_drawingProblems->setObjectName(QStringLiteral("trackPlanDrawingProblems"));
    m_drawingProblems->setTone(ProblemBar::Tone::Notice);
    layout->addWidget(m_drawingProblems);
    m_blockPopup = new BlockPopup(this);
    m_layoutState = new LayoutStateBanner(this);
    m_layoutState->setObjectName(QStringLiteral("trackPlanLayoutState"));
    layout->addWidget(m_layoutState);
    m_planAutomation = new PlanAutomation(this);
    connect(m_planAutomation, &PlanAutomation::changed, this, &TrackPlanPanel::automationChanged);
    m_legend = new BlockLegend(this);
    m_legend->hide(); // while an automation runs
    layout->addWidget(m_legend);

    m_emptyText = new QLabel(this);
    m_emptyText->setAlignment(Qt::AlignCenter);
    m_emptyText->setEnabled(false);
    layout->addWidget(m_emptyText, 1);
    m_tabs = new QTabWidget(this);
    m_zoom = new PageZoom(m_tabs, this);
    m_tabs->setObjectName(QStringLiteral("trackPlanPages"));
    m_tabs->setDocumentMode(true);
    // Where the plan is from, beside its pages: a remark in grey, not a button.
    m_source = new QLabel(m_tabs);
    m_source->setObjectName(QStringLiteral("trackPlanSource"));
    m_source->setForegroundRole(QPalette::PlaceholderText);
    m_source->setContentsMargins(8, 0, 8, 0);
    m_tabs->setCornerWidget(m_source, Qt::TopRightCorner);
    layout->addWidget(m_tabs, 1);
    setLayoutInUse(new model::LayoutInUse(this));
}

TrackPlanPanel::~TrackPlanPanel() = default;

void TrackPlanPanel::setRailway(model::Railway* railway) {
    if (m_railway) {
        disconnect(m_railway, nullptr, this, nullptr);
        disconnect(&m_railway->blockStates(), nullptr, this, nullptr);
    }
    m_railway = railway;
    if (m_railway) {
        connect(&m_railway->blockStates(), &model::BlockStates::changed, this,
                &TrackPlanPanel::applyBlockStates);
        connect(m_railway, &model::Railway::loaded, this, &TrackPlanPanel::railwayLoaded);
        connect(m_railway, &model::Railway::tilesChanged, this, &TrackPlanPanel::tilesChanged);
        connect(m_railway, &model::Railway::routeStarted, this, &TrackPlanPanel::routeChanged);
        connect(m_railway, &model::Railway::routeFinished, this, &TrackPlanPanel::routeChanged);
        connect(m_railway, &model::Railway::routeFailed, this, [this](qint64 route) { routeChanged(route); });
        connect(m_railway, &model::Railway::stateReportedChanged, this,
                &TrackPlanPanel::stateReportedChanged);
        connect(m_railway, &model::Railway::accessoriesChanged, this, &TrackPlanPanel::updateSetRoutes);
        connect(m_railway, &model::Railway::routeFinished, this, &TrackPlanPanel::updateSetRoutes);
        connect(m_railway, &model::Railway::stateReportedChanged, this, &TrackPlanPanel::updateSetRoutes);
        connect(m_railway, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    m_layoutState->setRailway(railway);
    m_planAutomation->setRailway(railway);
    if (!showsFolder())
        rebuild();
    updateActions();
}

void TrackPlanPanel::setLayoutInUse(model::LayoutInUse* layout) {
    if (m_layoutInUse) {
        disconnect(m_layoutInUse, nullptr, this, nullptr);
        if (m_layoutInUse->parent() == this) // the panel's own, until it was given one
            m_layoutInUse->deleteLater();
    }
    m_layoutInUse = layout;
    connect(m_layoutInUse, &model::LayoutInUse::changed, this, &TrackPlanPanel::rebuild);
    rebuild();
}

// The railway read the station again: its states are new, the pages are the layout in use's.
void TrackPlanPanel::railwayLoaded() {
    m_setRoutes->update(isLive() ? m_railway.data() : nullptr);
    stateReportedChanged();
    for (TrackPageView* view : m_views)
        if (view)
            view->update();
}

bool TrackPlanPanel::showsFolder() const {
    return m_layoutInUse->origin() == model::LayoutInUse::Origin::Folder;
}

bool TrackPlanPanel::openFolder(const QString& folder) {
    if (const std::string problem = m_layoutInUse->open(folder.toStdString()); !problem.empty()) {
        showProblem([problem = QString::fromStdString(problem)] {
            return tr("Cannot open the layout: %1").arg(problem);
        });
        return false;
    }
    showOpenedFolder();
    return true;
}

// What opening the folder in use found: a missing index, files that disagree (nothing: the bar hides).
void TrackPlanPanel::showOpenedFolder() {
    const cs2config::LayoutFolder::Content& content = *m_layoutInUse->folderContent();
    const bool withoutIndex = content.extent == cs2config::LayoutFolder::Extent::PagesOnly;
    showProblem([withoutIndex, findings = content.findings, pages = int(content.layout.pages.size()),
                 index = content.configDirectory / "gleisbild.cs2"] {
        QStringList parts;
        if (withoutIndex)
            parts << tr("%1 is missing: the %n page file(s) found in gleisbilder/ are shown in the order of "
                        "their names. Export the layout to write a new gleisbild.cs2 for them.",
                        "", pages)
                         .arg(QString::fromStdString(index.string()));
        if (!findings.empty())
            parts << findingsText(findings);
        return parts.join(QLatin1Char('\n'));
    });
}

// What the layout check found, the first few in full (`stellwerk-cli cs2 check DIR` lists them all).
QString TrackPlanPanel::findingsText(const std::vector<cs2config::LayoutFinding>& findings) {
    if (findings.empty())
        return {};
    constexpr int Shown = 5;
    QStringList lines{tr("The layout's files disagree in %n place(s):", "", int(findings.size()))};
    for (std::size_t i = 0; i < findings.size() && i < std::size_t(Shown); ++i) {
        const cs2config::LayoutFinding& finding = findings[i];
        const QString where =
            finding.line > 0
                ? QStringLiteral("%1:%2").arg(QString::fromStdString(finding.file)).arg(finding.line)
                : QString::fromStdString(finding.file);
        lines << QStringLiteral("%1: %2").arg(where, QString::fromStdString(finding.message));
    }
    if (findings.size() > std::size_t(Shown))
        lines << tr("... and %n more.", "", int(findings.size()) - Shown);
    return lines.join(QLatin1Char('\n'));
}

void TrackPlanPanel::showStationPlan() {
    showProblem({});
    m_layoutInUse->showStation();
}

bool TrackPlanPanel::exportTo(const QString& folder) {
    if (!m_layoutInUse->hasPlan()) {
        showProblem([] {
            return tr("There is no track plan to export: connect to a station or open a layout first.");
        });
        return false;
    }
    const std::string problem = m_layoutInUse->exportTo(folder.toStdString());
    if (problem.empty())
        showProblem({});
    else
        showProblem([problem = QString::fromStdString(problem)] {
            return tr("Cannot export the layout: %1").arg(problem);
        });
    return problem.empty();
}

TrackPageView* TrackPlanPanel::pageView(int page) const {
    return page >= 0 && page < int(m_views.size()) ? m_views[std::size_t(page)] : nullptr;
}

void TrackPlanPanel::rebuild() {
    const int current = m_tabs->currentIndex();
    m_views.clear();
    while (m_tabs->count() > 0) {
        QWidget* page = m_tabs->widget(0);
        m_tabs->removeTab(0);
        delete page;
    }
    m_live = m_layoutInUse->origin() == model::LayoutInUse::Origin::Station && m_railway;
    m_layout = m_layoutInUse->pages();
    indexRoutes();
    m_setRoutes->update(m_live ? m_railway.data() : nullptr);
    m_graph = m_layout ? PlanGraph::of(m_layoutInUse->graph(), *m_layout) : nullptr;
    m_planAutomation->setShownGraph(m_graph ? &m_graph->graph() : nullptr);
    m_blockPopup->hide();
    if (m_layout)
        for (int i = 0; i < int(m_layout->pages().size()); ++i)
            addPage(i);
    applyBlocks();
    if (current >= 0 && current < m_tabs->count())
        m_tabs->setCurrentIndex(current);
    m_tabs->setVisible(m_tabs->count() > 0);
    m_emptyText->setVisible(m_tabs->count() == 0);
    updateActions();
    retranslate();
    emit layoutChanged();
}

void TrackPlanPanel::addPage(int index) {
    const model::LayoutPage& page = m_layout->pages()[std::size_t(index)];
    auto* scroll = new QScrollArea(m_tabs);
    scroll->setFrameShape(QFrame::NoFrame);
    const QString tabText = page.name.isEmpty() ? tr("Page %1").arg(page.id) : page.name;
    if (const QString empty = emptyPageText(index); !empty.isEmpty()) { // nothing to draw: say why
        auto* notice = new QLabel(empty, scroll);
        notice->setObjectName(QStringLiteral("emptyPageNotice"));
        notice->setAlignment(Qt::AlignCenter);
        notice->setWordWrap(true);
        notice->setMargin(24);
        notice->setToolTip(QString::fromStdString(
            m_layoutInUse->folderContent()->layout.pages[std::size_t(index)].file.string()));
        scroll->setWidgetResizable(true);
        scroll->setWidget(notice);
        m_views.push_back(nullptr);
        m_tabs->addTab(scroll, tabText);
        return;
    }
    auto* view = new TrackPageView(
        std::shared_ptr<const model::LayoutPage>(m_layout, &page),
        [this, index, shown = m_layout](int tile) {
            return lookOn(*shown, {index, tile});
        },
        [this, index, shown = m_layout](int tile) {
            return toolTipOn(*shown, {index, tile});
        },
        scroll);
    view->setDimmed(m_live && !isReported());
    view->setLocomotiveDrops(m_planAutomation->isActive());
    scroll->setWidget(view);
    m_zoom->attach(page.id, view, scroll);
    connect(view, &TrackPageView::tileClicked, this, [this, index](int tile) { tileClicked(index, tile); });
    connect(view, &TrackPageView::tileMenuRequested, this,
            [this, index](int tile, QPoint where) { showTileMenu(index, tile, where); });
    connect(
        view, &TrackPageView::locomotiveDropped, this,
        [this, index](quint32 locId, int tile, QPoint point) { placeDropped(index, tile, point, locId); });
    connect(view, &TrackPageView::zoomRequested, this, [this, view, id = page.id](int steps) {
        m_zoom->zoomTo(id, PageZoom::stepped(view->tileSize(), steps));
    });
    m_views.push_back(view);
    m_tabs->addTab(scroll, tabText);
}

// Why a page of an opened folder has nothing to show (its file is missing or unreadable); empty for a
// page that was read.
QString TrackPlanPanel::emptyPageText(int index) const {
    const cs2config::LayoutFolder::Content* folder = m_layoutInUse->folderContent();
    if (!showsFolder() || index < 0 || index >= int(folder->layout.pages.size()))
        return {};
    const cs2config::TrackLayoutPage& page = folder->layout.pages[std::size_t(index)];
    if (page.loaded)
        return {};
    if (page.file.empty())
        return tr(
            "This page has nothing to show: its name cannot be a file name, so no file was looked for.");
    const QString file = QString::fromStdString(page.diagnostics.fileName()); // gleisbilder/<page>.cs2
    return page.missing ? tr("This page has nothing to show: its file %1 is missing.").arg(file)
                        : tr("This page has nothing to show: its file %1 could not be read.").arg(file);
}

void TrackPlanPanel::indexRoutes() {
    m_routeTiles.clear();
    if (!m_layout)
        return;
    for (int p = 0; p < int(m_layout->pages().size()); ++p) {
        const auto& tiles = m_layout->pages()[std::size_t(p)].tiles;
        for (int t = 0; t < int(tiles.size()); ++t)
            if (tiles[std::size_t(t)].route)
                m_routeTiles[*tiles[std::size_t(t)].route].push_back({p, t});
    }
}

TrackTileLook TrackPlanPanel::lookOf(model::TileRef ref) const {
    return lookOn(*m_layout, ref);
}

QString TrackPlanPanel::toolTipOf(model::TileRef ref) const {
    return toolTipOn(*m_layout, ref);
}

// `layout` may be one the panel no longer shows (a page view kept beyond a rebuild): then only its tiles.
TrackTileLook TrackPlanPanel::lookOn(const model::TrackLayout& layout, model::TileRef ref) const {
    const model::LayoutTile& tile = layout.tile(ref);
    TrackTileLook look{tile.type, tile.category, tile.rotation, -1, false, false, tile.text};
    if (!isLive() || &layout != m_layout.get())
        return look;
    if (tile.accessory)
        if (const model::Accessory* accessory = m_railway->accessory(*tile.accessory))
            look.position = accessory->position();
    if (tile.contact)
        if (const model::FeedbackContact* contact = m_railway->contact(*tile.contact)) {
            look.occupied = contact->occupied();
            look.occupant = occupantName(*contact);
        }
    if (tile.route)
        if (const model::Route* route = m_railway->route(*tile.route))
            look.running = route->running();
    look.onRoute = (tile.route && m_setRoutes->isSet(*tile.route)) ||
                   (tile.accessory && m_setRoutes->holds(*tile.accessory));
    return look;
}

QString TrackPlanPanel::toolTipOn(const model::TrackLayout& layout, model::TileRef ref) const {
    const model::LayoutTile& tile = layout.tile(ref);
    if (&layout != m_layout.get())
        return TrackTileInfo::toolTip(tile, QString());
    QString name;
    if (tile.accessory)
        name = accessoryName(*tile.accessory);
    else if (tile.route && isLive())
        if (const model::Route* route = m_railway->route(*tile.route))
            name = route->name();
    QString tip = TrackTileInfo::toolTip(tile, name);
    if (tile.contact && isLive())
        if (const model::FeedbackContact* contact = m_railway->contact(*tile.contact); contact)
            if (const QString occupant = occupantName(*contact); !occupant.isEmpty())
                tip += QStringLiteral("\n") + tr("Locomotive on it: %1").arg(occupant);
    if (tile.route && isLive())
        tip += memoryToolTip(*tile.route);
    const bool hasState = tile.accessory || tile.contact || tile.route;
    if (hasState && isLive() && !isReported())
        tip += QStringLiteral("\n") + NotReported::reason();
    return tip + automationToolTip(ref) + graphToolTip(ref);
}

// A route's memory slot on the station, and what the station last announced for it.
QString TrackPlanPanel::memoryToolTip(std::int64_t route) const {
    const QString slot = model::BlockStates::memorySlotOfRoute(route);
    if (slot.isEmpty())
        return {};
    const auto state = m_railway->blockStates().routeState(route);
    return QStringLiteral("\n") +
           (state ? tr("Station memory %1: %2").arg(slot, AnnouncedStateText::of(state->meaning()))
                  : tr("Station memory %1").arg(slot));
}

// While the blocks are shown: the block a tile is in, and the drawing's problems there.
QString TrackPlanPanel::graphToolTip(model::TileRef tile) const {
    if (!showsBlocks() || !m_graph)
        return {};
    QString tip;
    const trackgraph::TrackGraph& graph = m_graph->graph();
    for (const int block : m_graph->blocksAt(tile)) {
        tip += QStringLiteral("\n") +
               tr("Block %1 '%2'").arg(block).arg(QString::fromStdString(graph.block(block).name));
        if (const QString state = announcedStateOf(block); !state.isEmpty())
            tip += QStringLiteral("\n") + tr("Announced on the station's bus: %1").arg(state);
    }
    for (const trackgraph::Problem* problem : m_graph->problemsAt(tile))
        tip += QStringLiteral("\n") + tr("Problem: %1").arg(GraphProblemText::sentence(graph, *problem));
    return tip;
}

// The name of the locomotive on an occupied contact, where the simulator or the user said which it is.
QString TrackPlanPanel::occupantName(const model::FeedbackContact& contact) const {
    const model::Locomotive* locomotive = m_railway->locomotiveOn(contact);
    return locomotive ? locomotive->displayName() : QString();
}

bool TrackPlanPanel::isLive() const {
    return m_live && m_railway;
}

bool TrackPlanPanel::isReported() const {
    return m_railway && m_railway->isStateReported();
}

// Greyed while not reported; the states drawn come back as they were read again.
void TrackPlanPanel::stateReportedChanged() {
    for (TrackPageView* view : m_views)
        if (view)
            view->setDimmed(isLive() && !isReported());
}

// The railway's names while live (they may have been changed since the download), else the files'.
QString TrackPlanPanel::accessoryName(std::int64_t id) const {
    if (!isLive())
        return QString::fromStdString(m_layoutInUse->accessoryName(id));
    const model::Accessory* accessory = m_railway->accessory(id);
    return accessory ? accessory->name() : QString();
}

QString TrackPlanPanel::routeName(std::int64_t id) const {
    if (!isLive())
        return QString::fromStdString(m_layoutInUse->routeName(id));
    const model::Route* route = m_railway->route(id);
    return route ? route->name() : QString();
}

void TrackPlanPanel::tilesChanged(const QList<model::TileRef>& tiles) {
    if (!isLive())
        return;
    for (const model::TileRef& ref : tiles)
        if (TrackPageView* view = pageView(ref.page))
            view->updateTile(ref.tile);
}

// A route became set or stopped being set: the plan repaints (rare, and it may touch several pages).
void TrackPlanPanel::updateSetRoutes() {
    if (m_setRoutes->update(isLive() ? m_railway.data() : nullptr))
        for (TrackPageView* view : m_views)
            if (view)
                view->update();
}

void TrackPlanPanel::routeChanged(qint64 route) {
    const auto it = m_routeTiles.find(route);
    if (it == m_routeTiles.end() || !isLive())
        return;
    for (const model::TileRef& ref : it->second)
        if (TrackPageView* view = pageView(ref.page))
            view->updateTile(ref.tile);
}

void TrackPlanPanel::tileClicked(int page, int tile) {
    const model::LayoutTile& t = m_layout->tile({page, tile});
    if (t.page) {
        goToPage(*t.page);
        return;
    }
    if (!t.route && !t.accessory && showBlockAt({page, tile}))
        return; // a block's track or contact: what it leads to
    if (!isLive() || !isReported())
        return; // switching from a state nobody vouches for would be a guess
    if (t.route) {
        m_railway->runRoute(*t.route);
    } else if (t.accessory) {
        if (const model::Accessory* accessory = m_railway->accessory(*t.accessory))
            m_railway->switchAccessory(accessory->id(),
                                       (accessory->position() + 1) % std::max(1, accessory->positionCount()));
    }
}

void TrackPlanPanel::showTileMenu(int page, int tile, QPoint where) {
    QMenu menu(this);
    if (fillTileMenu(menu, {page, tile}))
        menu.exec(where);
}

bool TrackPlanPanel::fillTileMenu(QMenu& menu, model::TileRef tile) {
    bool filled = isLive() && isReported() && TileMenu::fill(menu, m_layout->tile(tile), *m_railway);
    filled = fillTrainEntries(menu, tile, filled);
    if (!showsBlocks() || !m_graph)
        return filled;
    for (const int block : m_graph->blocksAt(tile)) {
        if (filled)
            menu.addSeparator();
        const QString name = QString::fromStdString(m_graph->graph().block(block).name);
        QAction* entry = menu.addAction(tr("Block %1 '%2'...").arg(block).arg(name));
        entry->setObjectName(QStringLiteral("blockEntry"));
        connect(entry, &QAction::triggered, this, [this, tile, block] { showBlock(tile, block); });
        filled = true;
    }
    return filled;
}

bool TrackPlanPanel::showsBlocks() const {
    return m_blocks->isChecked();
}

void TrackPlanPanel::setShowBlocks(bool shown) {
    m_blocks->setChecked(shown);
}

bool TrackPlanPanel::showBlockAt(model::TileRef tile) {
    if (!showsBlocks() || !m_graph)
        return false;
    const std::vector<int> blocks = m_graph->blocksAt(tile);
    if (blocks.empty())
        return false;
    showBlock(tile, blocks.front());
    return true;
}

// The popup about a block, just below the tile it was asked from.
void TrackPlanPanel::showBlock(model::TileRef tile, int block) {
    TrackPageView* view = pageView(tile.page);
    if (!m_graph || !view)
        return;
    const BlockDescription description(m_graph->graph(),
                                       {[this](std::int64_t id) { return accessoryName(id); },
                                        [this](std::int64_t id) { return routeName(id); }});
    const QRect cell = view->tileRect(tile.tile);
    m_blockPopup->showText(description.html(block), view->mapToGlobal(cell.bottomLeft() + QPoint(0, 4)));
}

// The blocks drawn over every page, the drawing's problems marked and listed, or none of it; the
// automation's blocks and ways whenever one runs.
void TrackPlanPanel::applyBlocks() {
    const bool shown = showsBlocks() && m_graph;
    const bool marked = m_graph && m_planAutomation->isActive();
    for (int i = 0; i < int(m_views.size()); ++i)
        if (TrackPageView* view = m_views[std::size_t(i)]) {
            view->setBlocks(shown || marked ? outlinesOf(i, shown) : BlockOutlines());
            view->setProblemTiles(shown ? m_graph->problemTilesOf(i) : std::vector<int>());
        }
    if (shown && !m_graph->graph().problems().empty())
        m_drawingProblems->setProblem([graph = m_graph] { return GraphProblemText::list(graph->graph()); });
    else
        m_drawingProblems->clear();
    if (!shown)
        m_blockPopup->hide();
}

// Another program announced block states on the bus: the blocks' names say them.
void TrackPlanPanel::applyBlockStates() {
    const bool shown = showsBlocks() && m_graph;
    if (!shown && !(m_graph && m_planAutomation->isActive()))
        return;
    for (int i = 0; i < int(m_views.size()); ++i)
        if (TrackPageView* view = m_views[std::size_t(i)])
            view->setBlocks(outlinesOf(i, shown));
}

// A page's blocks named with what was announced for them, or, while an automation runs, shaded as it has
// them (every block, or only those not free) with its reserved ways.
BlockOutlines TrackPlanPanel::outlinesOf(int page, bool allBlocks) const {
    if (!m_planAutomation->isActive())
        return BlockOutlines::ofPage(*m_graph, page, [this](int block) { return announcedStateOf(block); });
    return BlockOutlines::ofPage(
        *m_graph, page,
        [this](int block) {
            BlockOutlines::Mark mark = m_planAutomation->markOf(block);
            if (mark.words.isEmpty())
                mark.words = announcedStateOf(block);
            return mark;
        },
        allBlocks, m_planAutomation->trains().ways());
}

QString TrackPlanPanel::announcedStateOf(int block) const {
    if (!isLive())
        return {};
    const auto state = m_railway->blockStates().blockState(block);
    return state ? AnnouncedStateText::of(state->meaning()) : QString();
}

void TrackPlanPanel::goToPage(std::int64_t pageId) {
    for (int i = 0; i < int(m_layout->pages().size()); ++i)
        if (m_layout->pages()[std::size_t(i)].id == pageId)
            m_tabs->setCurrentIndex(i);
}

void TrackPlanPanel::zoomIn() {
    setTileSize(PageZoom::stepped(tileSize(), 1));
}

void TrackPlanPanel::zoomOut() {
    setTileSize(PageZoom::stepped(tileSize(), -1));
}

QString TrackPlanPanel::problemText() const {
    return m_problem->text();
}

void TrackPlanPanel::showProblem(std::function<QString()> describe) {
    m_problem->setProblem(std::move(describe));
}

bool TrackPlanPanel::mayOpen() const {
    return !m_mayOpen || m_mayOpen();
}

void TrackPlanPanel::updateActions() {
    m_station->setVisible(showsFolder() && m_railway);
    m_export->setEnabled(m_layoutInUse->hasPlan());
    const bool drawn =
        std::any_of(m_views.begin(), m_views.end(), [](const TrackPageView* view) { return view; });
    for (QAction* action : {m_zoomIn, m_zoomOut, m_fit})
        action->setEnabled(drawn);
}

void TrackPlanPanel::retranslate() {
    m_open->setText(tr("Open layout..."));
    m_open->setToolTip(tr("Show the track plan of a CS2 configuration folder"));
    m_station->setText(tr("Station's plan"));
    m_export->setText(tr("Export layout..."));
    m_export->setToolTip(tr("Write the layout as a CS2 configuration folder"));
    m_zoomIn->setText(tr("Zoom in"));
    m_zoomOut->setText(tr("Zoom out"));
    m_fit->setText(tr("Fit"));
    m_blocks->setText(tr("Blocks"));
    m_blocks->setToolTip(
        tr("Outline each block with its name, and list and mark the problems of the drawing; "
           "then a click on a block's track says where it leads"));
    for (QAction* action : {m_zoomIn, m_zoomOut, m_fit})
        action->setToolTip(QStringLiteral("%1 (%2)").arg(
            action->text(), action->shortcut().toString(QKeySequence::NativeText)));
    m_emptyText->setText(tr("No track plan: connect to a station or open a CS2 layout folder."));
    // A folder by its name (the one holding config/), the whole path in the tooltip.
    const std::filesystem::path config = m_layoutInUse->folder();
    m_source->setText(
        showsFolder() ? tr("Files: %1").arg(QString::fromStdString(config.parent_path().filename().string()))
        : m_railway   ? tr("Live from the station")
                      : QString());
    m_source->setToolTip(QString::fromStdString(config.string()));
    m_blockPopup->hide(); // its words are in the language before
    applyBlockStates();   // so are the states on the blocks' tabs
    if (m_layout)
        for (int i = 0; i < m_tabs->count(); ++i) {
            if (m_layout->pages()[std::size_t(i)].name.isEmpty())
                m_tabs->setTabText(i, tr("Page %1").arg(m_layout->pages()[std::size_t(i)].id));
            if (auto* notice = m_tabs->widget(i)->findChild<QLabel*>(QStringLiteral("emptyPageNotice")))
                notice->setText(emptyPageText(i));
        }
}

void TrackPlanPanel::updateIcons() {
    using Tool = ToolIcons::Tool;
    ToolIcons::apply(*this, {{m_open, Tool::OpenLayout},
                             {m_station, Tool::StationPlan},
                             {m_export, Tool::ExportLayout},
                             {m_zoomOut, Tool::ZoomOut},
                             {m_zoomIn, Tool::ZoomIn},
                             {m_fit, Tool::Fit},
                             {m_blocks, Tool::Blocks}});
}

void TrackPlanPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    if (event->type() == QEvent::PaletteChange)
        updateIcons();
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
