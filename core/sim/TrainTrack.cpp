#include "sim/TrainTrack.h"

#include "cs2config/TrackElementType.h"

#include <algorithm>
#include <tuple>

namespace stellwerk::sim {

namespace {

bool validTarget(int index, std::size_t count) {
    return index == SectionExit::BufferStop || (index >= 0 && std::size_t(index) < count);
}

bool validExit(const SectionExit& exit, std::size_t count) {
    return validTarget(exit.next, count) && (exit.turnout == 0 || validTarget(exit.diverging, count));
}

struct ContactTile {
    std::tuple<int, int, int> where; // page, row, column
    std::uint16_t device = 0;
    std::uint16_t contact = 0;
    std::string name;
};

std::vector<ContactTile> contactTiles(const cs2config::TrackLayout& layout) {
    std::vector<ContactTile> tiles;
    for (const cs2config::TrackLayoutPage& page : layout.pages)
        for (const cs2config::TrackElement& element : page.page.elements) {
            if (element.articleLink() != cs2config::ArticleLink::FeedbackContact || element.article < 0)
                continue;
            const int pageNumber = int(page.id);
            tiles.push_back({{pageNumber, element.position.row, element.position.column},
                             std::uint16_t(element.deviceId),
                             std::uint16_t(element.article),
                             element.text.empty() ? "S88 " + std::to_string(element.article) : element.text});
        }
    std::ranges::sort(tiles, {}, &ContactTile::where);
    std::vector<ContactTile> unique; // a contact drawn on two pages is still one section
    for (ContactTile& tile : tiles)
        if (std::ranges::none_of(unique, [&](const ContactTile& seen) {
                return seen.device == tile.device && seen.contact == tile.contact;
            }))
            unique.push_back(std::move(tile));
    return unique;
}

} // namespace

std::optional<int> TrainTrack::find(std::string_view name) const {
    for (std::size_t i = 0; i < sections.size(); ++i)
        if (sections[i].name == name)
            return int(i);
    return std::nullopt;
}

bool TrainTrack::consistent() const {
    const std::size_t count = sections.size();
    for (const FeedbackSection& section : sections)
        if (section.lengthMm <= 0 || !validExit(section.ahead, count) || !validExit(section.behind, count))
            return false;
    return std::ranges::all_of(placements, [count](const TrainPlacement& placement) {
        return placement.section >= 0 && std::size_t(placement.section) < count;
    });
}

TrainTrack TrainTrack::loopOfContacts(const cs2config::TrackLayout& layout,
                                      const std::vector<std::uint32_t>& locIds) {
    TrainTrack track;
    const std::vector<ContactTile> tiles = contactTiles(layout);
    const int count = int(tiles.size());
    for (int i = 0; i < count; ++i) {
        FeedbackSection section{tiles[std::size_t(i)].name,
                                tiles[std::size_t(i)].device,
                                tiles[std::size_t(i)].contact,
                                1500,
                                {},
                                {}};
        section.ahead.next = (i + 1) % count;
        section.behind.next = (i + count - 1) % count;
        track.sections.push_back(std::move(section));
    }
    if (count < 2)
        return track; // a single contact is no loop to run on
    const std::size_t trains = std::min<std::size_t>({locIds.size(), 3, std::size_t(count)});
    for (std::size_t i = 0; i < trains; ++i)
        track.placements.push_back({locIds[i], int(i * std::size_t(count) / trains), 1200});
    return track;
}

} // namespace stellwerk::sim
