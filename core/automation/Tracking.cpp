#include "automation/Tracking.h"

#include <algorithm>

namespace stellwerk::automation {

using trackgraph::End;

void Tracking::place(std::uint32_t locId, int block, End towards, int lengthMm) {
    TrainBody body;
    body.frontBlock = block;
    body.towards = towards;
    body.lengthMm = lengthMm;
    const trackgraph::Block& placed = graph_.block(block);
    const std::size_t last = placed.contacts.empty() ? 0 : placed.contacts.size() - 1;
    const int contactEnd =
        placed.contacts.empty() ? placed.lengthMm : contactSpan(block, last, towards).second;
    body.frontMm = std::min(placed.lengthMm, std::max(contactEnd, lengthMm));
    bodies_[locId] = body;
    ghosts_.erase(block);
}

void Tracking::advanced(std::uint32_t locId, int frontMm) {
    if (const auto found = bodies_.find(locId); found != bodies_.end())
        found->second.frontMm = std::max(found->second.frontMm, frontMm);
}

bool Tracking::reverse(std::uint32_t locId) {
    const auto found = bodies_.find(locId);
    if (found == bodies_.end() || !found->second.behind.empty())
        return false;
    TrainBody& body = found->second;
    const int length = graph_.block(body.frontBlock).lengthMm;
    const int rear = std::max(0, body.frontMm - body.lengthMm);
    body.towards = trackgraph::otherEnd(body.towards);
    body.frontMm = std::clamp(length - rear, std::min(body.lengthMm, length), length);
    return true;
}

void Tracking::remove(std::uint32_t locId) {
    bodies_.erase(locId);
}

std::pair<int, int> Tracking::contactSpan(int block, std::size_t index, End towards) const {
    const trackgraph::Block& on = graph_.block(block);
    if (towards == End::B) {
        const trackgraph::ContactOnBlock& contact = on.contacts[index];
        return {contact.fromMm, contact.toMm};
    }
    const trackgraph::ContactOnBlock& contact = on.contacts[on.contacts.size() - 1 - index];
    return {on.lengthMm - contact.toMm, on.lengthMm - contact.fromMm};
}

std::size_t Tracking::travelIndex(int block, const trackgraph::ContactKey& contact, End towards) const {
    const trackgraph::Block& on = graph_.block(block);
    std::size_t index = 0;
    while (index < on.contacts.size() && !(on.contacts[index].contact == contact))
        ++index;
    return towards == End::B ? index : on.contacts.size() - 1 - index;
}

Sighting Tracking::occupied(const trackgraph::ContactKey& contact, const ExpectedNext& expected) {
    occupied_.insert(contact);
    const std::optional<int> block = graph_.blockWithContact(contact);
    if (!block)
        return Sighting{};
    for (auto& [locId, body] : bodies_)
        if (body.frontBlock == *block) {
            const std::size_t index = travelIndex(*block, contact, body.towards);
            body.frontMm = std::max(body.frontMm, contactSpan(*block, index, body.towards).first);
            return {Sighting::Kind::Moved, locId, *block, 0, int(index)};
        }
    if (trainIn(*block) != 0)
        return Sighting{};
    for (auto& [locId, body] : bodies_)
        if (const std::optional<NextBlock> next = expected(locId); next && next->block == *block)
            return enter(locId, body, *next, contact);
    ghosts_.insert(*block);
    return {Sighting::Kind::Ghost, 0, *block, 0, 0};
}

Sighting Tracking::enter(std::uint32_t locId, TrainBody& body, const NextBlock& next,
                         const trackgraph::ContactKey& contact) {
    const trackgraph::Connection& way = graph_.connection(next.connection);
    body.behind.push_back({true, body.frontBlock, graph_.block(body.frontBlock).lengthMm});
    body.behind.push_back({false, next.connection, way.lengthMm});
    body.frontBlock = next.block;
    body.towards = trackgraph::otherEnd(way.to.end);
    const std::size_t index = travelIndex(next.block, contact, body.towards);
    body.frontMm = contactSpan(next.block, index, body.towards).first;
    return {Sighting::Kind::Entered, locId, next.block, next.connection, int(index)};
}

std::optional<int> Tracking::freed(const trackgraph::ContactKey& contact) {
    occupied_.erase(contact);
    const std::optional<int> block = graph_.blockWithContact(contact);
    if (!block || !ghosts_.contains(*block) || blockOccupied(*block))
        return std::nullopt;
    ghosts_.erase(*block);
    return block;
}

std::vector<int> Tracking::reread(const std::set<trackgraph::ContactKey>& occupied) {
    occupied_ = occupied;
    ghosts_.clear();
    for (const trackgraph::ContactKey& contact : occupied)
        if (const std::optional<int> block = graph_.blockWithContact(contact); block && trainIn(*block) == 0)
            ghosts_.insert(*block);
    return {ghosts_.begin(), ghosts_.end()};
}

std::vector<BodySegment> Tracking::left(std::uint32_t locId) {
    const auto found = bodies_.find(locId);
    if (found == bodies_.end())
        return {};
    TrainBody& body = found->second;
    // Walk back from the front: the first piece the length no longer reaches, and all before it, are behind.
    int covered = body.frontMm;
    std::size_t behindRear = 0;
    for (std::size_t i = body.behind.size(); i > 0; --i) {
        if (covered >= body.lengthMm) {
            behindRear = i;
            break;
        }
        covered += body.behind[i - 1].lengthMm;
    }
    std::vector<BodySegment> gone;
    for (std::size_t i = 0; i < behindRear; ++i) {
        const BodySegment& segment = body.behind[i];
        if (segment.isBlock && blockOccupied(segment.id))
            break; // its contacts say the train is still there: keep it and what lies ahead of it
        gone.push_back(segment);
    }
    body.behind.erase(body.behind.begin(), body.behind.begin() + std::ptrdiff_t(gone.size()));
    return gone;
}

const TrainBody* Tracking::body(std::uint32_t locId) const {
    const auto found = bodies_.find(locId);
    return found == bodies_.end() ? nullptr : &found->second;
}

std::uint32_t Tracking::trainIn(int block) const {
    for (const auto& [locId, body] : bodies_) {
        if (body.frontBlock == block)
            return locId;
        for (const BodySegment& segment : body.behind)
            if (segment.isBlock && segment.id == block)
                return locId;
    }
    return 0;
}

std::vector<int> Tracking::blocksOf(std::uint32_t locId) const {
    std::vector<int> blocks;
    if (const TrainBody* on = body(locId)) {
        blocks.push_back(on->frontBlock);
        for (auto segment = on->behind.rbegin(); segment != on->behind.rend(); ++segment)
            if (segment->isBlock)
                blocks.push_back(segment->id);
    }
    return blocks;
}

bool Tracking::blockOccupied(int block) const {
    const trackgraph::Block& on = graph_.block(block);
    return std::any_of(
        on.contacts.begin(), on.contacts.end(),
        [&](const trackgraph::ContactOnBlock& contact) { return occupied_.contains(contact.contact); });
}

} // namespace stellwerk::automation
