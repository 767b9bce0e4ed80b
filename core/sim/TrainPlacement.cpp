#include "sim/TrainPlacement.h"

#include "cs2/LocIdText.h"

#include <algorithm>
#include <charconv>

namespace stellwerk::sim {

namespace {

constexpr std::size_t MostSpreadTrains = 3;

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

std::optional<std::int64_t> contactNumber(std::string_view text) {
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0)
        return std::nullopt;
    return value;
}

Expected<trackgraph::End, std::string> endNamed(std::string_view text) {
    if (text == "a" || text == "A")
        return trackgraph::End::A;
    if (text == "b" || text == "B")
        return trackgraph::End::B;
    return "the end " + quoted(text) + " is not a or b";
}

} // namespace

Expected<TrainPlacement, std::string> parsePlacement(std::string_view text) {
    const std::size_t equals = text.find('=');
    if (equals == std::string_view::npos)
        return quoted(text) + " is not LOC=CONTACT[:END] (e.g. mfx:5=12:a)";
    const auto loco = cs2::parseLocomotive(text.substr(0, equals));
    if (!loco)
        return loco.error();
    std::string_view place = text.substr(equals + 1);
    TrainPlacement placement{loco->value(), 0, trackgraph::End::B};
    if (const std::size_t colon = place.find(':'); colon != std::string_view::npos) {
        const auto end = endNamed(place.substr(colon + 1));
        if (!end)
            return end.error();
        placement.towards = *end;
        place = place.substr(0, colon);
    }
    const std::optional<std::int64_t> contact = contactNumber(place);
    if (!contact)
        return "the contact " + quoted(place) + " is not a contact number";
    placement.contact = *contact;
    return placement;
}

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
