#include "trackplan/PlanAutomation.h"

#include "automation/Automation.h"
#include "model/Railway.h"

#include <algorithm>

namespace stellwerk::ui {
namespace {

bool sameBlocks(const trackgraph::TrackGraph& a, const trackgraph::TrackGraph& b) {
    return std::equal(a.blocks().begin(), a.blocks().end(), b.blocks().begin(), b.blocks().end(),
                      [](const trackgraph::Block& x, const trackgraph::Block& y) {
                          return x.id == y.id && x.name == y.name && x.tiles == y.tiles;
                      });
}

} // namespace

PlanAutomation::PlanAutomation(QObject* parent) : QObject(parent) {
    // Events and contacts come in bursts (a train entering a block releases the one behind): one look per
    // burst.
    m_batch.setSingleShot(true);
    m_batch.setInterval(0);
    connect(&m_batch, &QTimer::timeout, this, &PlanAutomation::refresh);
}

void PlanAutomation::setAutomation(automation::Automation* automation) {
    if (m_automation)
        disconnect(m_automation, nullptr, this, nullptr);
    m_automation = automation;
    if (m_automation) {
        connect(m_automation, &automation::Automation::happened, this, &PlanAutomation::schedule);
        connect(m_automation, &QObject::destroyed, this, &PlanAutomation::schedule);
    }
    match();
    refresh();
}

void PlanAutomation::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    if (m_railway) // a ghost leaves when its contacts turn free, which is no event of the automation's
        connect(m_railway, &model::Railway::contactsChanged, this, &PlanAutomation::schedule);
}

void PlanAutomation::setShownGraph(const trackgraph::TrackGraph* graph) {
    m_shownGraph = graph;
    match();
    refresh();
}

void PlanAutomation::match() {
    m_matches = m_automation && m_shownGraph && sameBlocks(m_automation->dispatcher().graph(), *m_shownGraph);
}

void PlanAutomation::schedule() {
    if (!m_batch.isActive())
        m_batch.start();
}

void PlanAutomation::refresh() {
    m_batch.stop();
    if (!m_automation)
        m_matches = false;
    TrainsOnPlan now = isActive() ? TrainsOnPlan::of(m_automation->dispatcher()) : TrainsOnPlan();
    if (now == m_trains && isActive() == m_wasActive)
        return;
    m_trains = std::move(now);
    m_wasActive = isActive();
    emit changed();
}

BlockOutlines::Mark PlanAutomation::markOf(int block) const {
    using Kind = TrainsOnPlan::BlockState::Kind;
    if (!isActive())
        return {};
    const TrainsOnPlan::BlockState state = m_trains.block(block);
    switch (state.kind) {
    case Kind::Free:
        return {BlockShade::Free, QString()};
    case Kind::Reserved:
        return {BlockShade::Reserved, tr("for %1", "a block reserved for a train").arg(state.train)};
    case Kind::Occupied:
        return {BlockShade::Occupied, state.train};
    case Kind::Ghost:
        return {BlockShade::Ghost, tr("unknown occupant")};
    case Kind::Fault:
        return {BlockShade::Fault, tr("%1 · fault", "a train stopped by a fault").arg(state.train)};
    }
    return {};
}

QString PlanAutomation::toolTipOf(int block) const {
    using Kind = TrainsOnPlan::BlockState::Kind;
    if (!isActive())
        return {};
    const TrainsOnPlan::BlockState state = m_trains.block(block);
    switch (state.kind) {
    case Kind::Free:
        return tr("Automation: free");
    case Kind::Reserved:
        return tr("Automation: reserved for %1 (hatched)").arg(state.train);
    case Kind::Occupied:
        return tr("Automation: %1 is in this block (solid)").arg(state.train);
    case Kind::Ghost:
        return tr("Automation: an unknown occupant, no train can have reached it (cross-hatched); no "
                  "automatic train enters it");
    case Kind::Fault:
        return tr("Automation: %1 stopped by a fault (dotted); see the Automatic panel").arg(state.train);
    }
    return {};
}

std::optional<QString> PlanAutomation::place(std::uint32_t locId, int block, trackgraph::End towards,
                                             int lengthMm, bool pushPull) {
    if (!isActive())
        return tr("No automation runs on this layout.");
    const TrainsOnPlan::BlockState there = TrainsOnPlan::of(m_automation->dispatcher()).block(block);
    if (there.locId != 0 && there.locId != locId) // the usual refusals in the user's words
        return there.kind == TrainsOnPlan::BlockState::Kind::Reserved
                   ? tr("The block is reserved for %1: choose another block.").arg(there.train)
                   : tr("%1 is in this block already: remove it first.").arg(there.train);
    const std::optional<std::string> problem = m_automation->placeInBlock(locId, block, towards, lengthMm);
    if (!problem)
        m_automation->setPushPull(locId, pushPull);
    refresh();
    if (problem)
        return QString::fromStdString(*problem);
    return std::nullopt;
}

bool PlanAutomation::remove(std::uint32_t locId) {
    const bool removed = isActive() && m_automation->remove(locId);
    refresh();
    return removed;
}

} // namespace stellwerk::ui
