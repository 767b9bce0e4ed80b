// The track plan's part in automatic operation (TrackPlanPanel's functions about trains): the automation
// followed, its states in the tooltips, trains placed from a block's menu or by a locomotive dropped on a
// block, and taken off again.
#include "common/PlaceTrainDialog.h"
#include "model/Railway.h"
#include "trackplan/BlockLegend.h"
#include "trackplan/PlanAutomation.h"
#include "trackplan/PlanGraph.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"

#include <QAction>
#include <QLineF>
#include <QMenu>
#include <algorithm>
#include <limits>

namespace stellwerk::ui {
namespace {

constexpr int DroppedLengthMm = 200; // a dropped locomotive: lokomotive.cs2 gives no length
constexpr trackgraph::TileId NoTile = std::numeric_limits<trackgraph::TileId>::max();

} // namespace

void TrackPlanPanel::setAutomation(automation::Automation* automation) {
    m_planAutomation->setAutomation(automation);
    automationChanged();
}

// The automation came, went or changed its mind about a block: the plan shows it.
void TrackPlanPanel::automationChanged() {
    const bool active = m_planAutomation->isActive();
    m_legend->setVisible(active && m_graph);
    for (TrackPageView* view : m_views)
        if (view)
            view->setLocomotiveDrops(active);
    applyBlocks();
}

QString TrackPlanPanel::automationToolTip(model::TileRef tile) const {
    if (!m_graph || !m_planAutomation->isActive())
        return {};
    QString tip;
    for (const int block : m_graph->blocksAt(tile))
        tip += QStringLiteral("\n") + m_planAutomation->toolTipOf(block);
    return tip;
}

// "Place a train in ..." for each block on the tile, and "Remove ..." for the train in it.
bool TrackPlanPanel::fillTrainEntries(QMenu& menu, model::TileRef tile, bool filled) {
    if (!m_graph || !m_planAutomation->isActive() || !isLive())
        return filled;
    for (const int block : m_graph->blocksAt(tile)) {
        if (filled)
            menu.addSeparator();
        const QString name = QString::fromStdString(m_graph->graph().block(block).name);
        QAction* place = menu.addAction(tr("Place a train in %1...").arg(name));
        place->setObjectName(QStringLiteral("placeTrainAction"));
        connect(place, &QAction::triggered, this, [this, block] { askToPlace(block); });
        if (const std::uint32_t locId = m_planAutomation->trains().trainIn(block); locId != 0) {
            const QString train = m_planAutomation->trains().block(block).train;
            QAction* remove = menu.addAction(tr("Remove %1 from %2").arg(train, name));
            remove->setObjectName(QStringLiteral("removeTrainAction"));
            connect(remove, &QAction::triggered, this, [this, locId] { m_planAutomation->remove(locId); });
        }
        filled = true;
    }
    return filled;
}

// The dialog asks which locomotive, facing which end, how long, push-pull or not; accepted, it is placed.
void TrackPlanPanel::askToPlace(int block) {
    if (!m_railway || !m_graph)
        return;
    PlaceTrainDialog::Choice start;
    start.block = block;
    auto* dialog = new PlaceTrainDialog(*m_railway, m_graph->graph(), start, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        const PlaceTrainDialog::Choice choice = dialog->choice();
        const std::optional<QString> problem = m_planAutomation->place(
            choice.locId, choice.block, choice.towards, choice.lengthMm, choice.pushPull);
        showProblem(problem ? std::function<QString()>([text = *problem] { return text; })
                            : std::function<QString()>());
    });
    dialog->open();
}

bool TrackPlanPanel::placeDropped(int page, int tile, QPoint point, std::uint32_t locId) {
    if (!m_graph || !m_planAutomation->isActive())
        return false;
    const std::vector<int> blocks = m_graph->blocksAt({page, tile});
    if (blocks.empty()) {
        showProblem([] { return tr("Drop the locomotive on a block's track to place it there."); });
        return false;
    }
    const int block = blocks.front();
    const std::optional<QString> problem =
        m_planAutomation->place(locId, block, endNearer(page, block, point), DroppedLengthMm);
    showProblem(problem ? std::function<QString()>([text = *problem] { return text; })
                        : std::function<QString()>());
    return !problem;
}

// The end of the block whose last tile is nearer the point, where both are drawn on this page; else the
// end nearer along the block's track from the tile under the point.
trackgraph::End TrackPlanPanel::endNearer(int page, int block, QPoint point) const {
    const trackgraph::Block& on = m_graph->graph().block(block);
    const TrackPageView* view = pageView(page);
    std::optional<double> distance[2];
    for (const trackgraph::End end : {trackgraph::End::A, trackgraph::End::B})
        if (const std::optional<model::TileRef> last = m_graph->planTile(on.end(end).tile);
            view && last && last->page == page)
            distance[int(end)] = QLineF(point, view->tileRect(last->tile).center()).length();
    if (distance[0] && distance[1])
        return *distance[0] <= *distance[1] ? trackgraph::End::A : trackgraph::End::B;
    const std::optional<int> under = view ? view->tileAt(point) : std::nullopt;
    const trackgraph::TileId graphTile = under ? m_graph->graphTile({page, *under}).value_or(NoTile) : NoTile;
    const auto step = std::find_if(on.path.begin(), on.path.end(),
                                   [&](const trackgraph::TrackStep& s) { return s.tile == graphTile; });
    return step - on.path.begin() < std::ptrdiff_t(on.path.size()) / 2 ? trackgraph::End::A
                                                                       : trackgraph::End::B;
}

} // namespace stellwerk::ui
