#include "trackplan/TrainsOnPlan.h"

#include "automation/Dispatcher.h"

namespace stellwerk::ui {
namespace {

bool atFault(const automation::Train& train) {
    return train.state == automation::TrainState::Fault || train.state == automation::TrainState::Lost;
}

} // namespace

TrainsOnPlan TrainsOnPlan::of(const automation::Dispatcher& dispatcher) {
    using Kind = BlockState::Kind;
    TrainsOnPlan shown;
    const auto nameOf = [&](std::uint32_t locId) {
        const automation::Train* train = dispatcher.train(locId);
        return train ? QString::fromStdString(train->name) : QString();
    };
    for (const trackgraph::Block& block : dispatcher.graph().blocks()) {
        if (const std::uint32_t in = dispatcher.tracking().trainIn(block.id); in != 0) {
            const automation::Train* train = dispatcher.train(in);
            shown.m_blocks[block.id] = {train && atFault(*train) ? Kind::Fault : Kind::Occupied, in,
                                        nameOf(in)};
        } else if (dispatcher.tracking().isGhost(block.id)) {
            shown.m_blocks[block.id] = {Kind::Ghost, 0, QString()};
        } else if (const std::uint32_t owner = dispatcher.reservations().blockOwner(block.id); owner != 0) {
            shown.m_blocks[block.id] = {Kind::Reserved, owner, nameOf(owner)};
        }
    }
    for (const trackgraph::Connection& connection : dispatcher.graph().connections())
        if (const std::uint32_t owner = dispatcher.reservations().connectionOwner(connection.id); owner != 0)
            shown.m_ways[connection.id] = owner;
    return shown;
}

TrainsOnPlan::BlockState TrainsOnPlan::block(int id) const {
    const auto found = m_blocks.find(id);
    return found == m_blocks.end() ? BlockState{} : found->second;
}

std::vector<int> TrainsOnPlan::ways() const {
    std::vector<int> ids;
    for (const auto& [id, owner] : m_ways)
        ids.push_back(id);
    return ids;
}

std::uint32_t TrainsOnPlan::trainIn(int block) const {
    const BlockState state = this->block(block);
    return state.kind == BlockState::Kind::Occupied || state.kind == BlockState::Kind::Fault ? state.locId
                                                                                             : 0;
}

} // namespace stellwerk::ui
