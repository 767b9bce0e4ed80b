#include "sim/TrainPlacement.h"

#include <algorithm>

namespace stellwerk::sim {

namespace {

constexpr std::size_t MostSpreadTrains = 3;

} // namespace

std::vector<TrainPlacement> demoPlacements() {
    // lokomotive.cs2: BR 218 Ost (mfx 0x4001), ICE 3 Velaro (mfx 0x4002), V 100 2023 (MM2 0x18), Köf III
    // (MM2 0x02); gleisbilder: Gleis 1 is contact 1, Block 2 contact 4, Gleis 2 contact 2, the
    // Abstellgleis 9.
    return {
        {0x4001, 1, trackgraph::End::B},
        {0x4002, 4, trackgraph::End::B},
        {0x0018, 2, trackgraph::End::B},
        {0x0002, 9, trackgraph::End::B},
    };
}

std::vector<TrainPlacement> spreadPlacements(const cs2config::LocomotiveFile& locomotives,
                                             const trackgraph::TrackGraph& graph) {
    std::vector<std::uint32_t> locIds;
    for (const cs2config::Locomotive& loco : locomotives.locomotives)
        if (loco.uid != 0 && loco.uid <= 0xFFFF) // not the placeholder record some stations write first
            locIds.push_back(loco.uid);
    const std::size_t blocks = graph.blocks().size();
    const std::size_t trains = std::min({locIds.size(), MostSpreadTrains, blocks});
    std::vector<TrainPlacement> placements;
    for (std::size_t i = 0; i < trains; ++i) {
        const trackgraph::Block& block = graph.blocks()[i * blocks / trains];
        placements.push_back({locIds[i], block.contacts.front().contact.number, trackgraph::End::B});
    }
    return placements;
}

} // namespace stellwerk::sim
