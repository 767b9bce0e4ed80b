// The blocks of GraphAssembly: each made from its first drawing, with the contacts of every drawing, and
// the drawings of one block compared with each other.
#include "trackgraph/GraphAssembly.h"

#include <algorithm>
#include <tuple>

namespace stellwerk::trackgraph {

namespace {

EndKind endKindOf(const PieceEnd& end) {
    if (end.neighbour)
        return EndKind::Block;
    switch (end.stretchEnd.kind) {
    case StretchEndKind::Junction:
        return EndKind::Junction;
    case StretchEndKind::BufferStop:
        return EndKind::BufferStop;
    case StretchEndKind::Turntable:
        return EndKind::Turntable;
    case StretchEndKind::OpenEnd:
        break;
    }
    return EndKind::OpenEnd;
}

// The contacts along steps from their start: one entry per contact, spanning every tile it is drawn on.
std::vector<ContactOnBlock> contactsAlong(const TrackTiles& tiles, const std::vector<TrackStep>& steps) {
    std::vector<ContactOnBlock> contacts;
    int at = 0;
    for (const TrackStep& step : steps) {
        const Tile& tile = tiles.tile(step.tile);
        if (tile.role() == TileRole::Contact) {
            const auto known =
                std::find_if(contacts.begin(), contacts.end(),
                             [&tile](const ContactOnBlock& c) { return c.contact == *tile.contact; });
            if (known != contacts.end())
                known->toMm = at + step.lengthMm;
            else
                contacts.push_back({*tile.contact, step.tile, tile.text, at, at + step.lengthMm});
        }
        at += step.lengthMm;
    }
    return contacts;
}

int lengthOf(const std::vector<TrackStep>& steps) {
    int length = 0;
    for (const TrackStep& step : steps)
        length += step.lengthMm;
    return length;
}

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
    std::string text;
    for (const std::string& part : parts)
        text += (text.empty() ? "" : separator) + part;
    return text;
}

std::string contactList(const std::vector<ContactKey>& contacts) {
    std::vector<std::string> numbers;
    for (const ContactKey& contact : contacts)
        numbers.push_back(std::to_string(contact.number));
    return joined(numbers, ", ");
}

} // namespace

void GraphAssembly::buildBlocks() {
    for (std::size_t index = 0; index < piecesOfBlock_.size(); ++index)
        graph_.blocks_.push_back(buildBlock(index));
    indexBlocks();
}

Block GraphAssembly::buildBlock(std::size_t index) const {
    const std::vector<std::uint32_t>& pieces = piecesOfBlock_[index];
    const std::uint32_t first = pieces.front();
    const BlockPiece& piece = pieces_[first];
    Block block;
    block.id = int(index + 1);
    block.path = orientedSteps(first);
    const std::size_t sideA = flipped_[first] ? 1 : 0;
    const auto info = [](const PieceEnd& end) { return BlockEndInfo{end.tile, end.port, endKindOf(end)}; };
    block.ends = {info(piece.ends[sideA]), info(piece.ends[1 - sideA])};
    block.lengthMm = lengthOf(block.path);
    addContacts(block, pieces);
    addSignals(block);
    for (const std::uint32_t p : pieces)
        for (const TrackStep& step : pieces_[p].steps)
            block.tiles.push_back(step.tile);
    std::sort(block.tiles.begin(), block.tiles.end());
    block.tiles.erase(std::unique(block.tiles.begin(), block.tiles.end()), block.tiles.end());
    block.name = BlockNaming(graph_.tiles_, source_.accessories, source_.routes).blockName(block);
    return block;
}

// The first drawing's contacts where it has them; a contact only other drawings show is placed where it
// lies on them, scaled to the first drawing's length.
void GraphAssembly::addContacts(Block& block, const std::vector<std::uint32_t>& pieces) const {
    block.contacts = contactsAlong(graph_.tiles_, block.path);
    for (std::size_t i = 1; i < pieces.size(); ++i) {
        const std::vector<TrackStep> steps = orientedSteps(pieces[i]);
        const double scale = double(block.lengthMm) / double(std::max(1, lengthOf(steps)));
        for (ContactOnBlock contact : contactsAlong(graph_.tiles_, steps)) {
            if (std::any_of(block.contacts.begin(), block.contacts.end(),
                            [&contact](const ContactOnBlock& c) { return c.contact == contact.contact; }))
                continue;
            contact.fromMm = int(contact.fromMm * scale);
            contact.toMm = int(contact.toMm * scale);
            block.contacts.push_back(contact);
        }
    }
    std::stable_sort(block.contacts.begin(), block.contacts.end(),
                     [](const ContactOnBlock& a, const ContactOnBlock& b) { return a.fromMm < b.fromMm; });
}

void GraphAssembly::addSignals(Block& block) const {
    const BlockNaming naming(graph_.tiles_, source_.accessories, source_.routes);
    int at = 0;
    for (const TrackStep& step : block.path) {
        const Tile& tile = graph_.tiles_.tile(step.tile);
        if (tile.role() == TileRole::Signal) {
            const End towards = step.entry == tile.shape.signalApproach ? End::B : End::A;
            block.signalsAlong.push_back(
                {step.tile, tile.accessory, naming.signalName(tile), towards, true, at + step.lengthMm / 2});
        }
        at += step.lengthMm;
    }
}

void GraphAssembly::indexBlocks() {
    graph_.tileBlocks_.assign(graph_.tiles_.size(), {0, 0});
    for (const Block& block : graph_.blocks_)
        for (const TileId tile : block.tiles) {
            std::array<int, 2>& slots = graph_.tileBlocks_[tile];
            if (slots[0] == 0)
                slots[0] = block.id;
            else if (slots[0] != block.id && slots[1] == 0)
                slots[1] = block.id;
        }
    for (std::uint32_t p = 0; p < pieces_.size(); ++p)
        for (std::uint8_t side = 0; side < 2; ++side) {
            const PieceEnd& end = pieces_[p].ends[side];
            graph_.endIndex_.push_back({(end.tile << 4) | std::uint32_t(end.port), blockEndOf({p, side})});
        }
    std::sort(graph_.endIndex_.begin(), graph_.endIndex_.end());
}

void GraphAssembly::checkDrawings() {
    for (const std::vector<std::uint32_t>& pieces : piecesOfBlock_)
        for (std::size_t i = 1; i < pieces.size(); ++i)
            compareDrawings(pieces[i], referenceOf_[pieces[i]]);
}

// Two drawings that share a contact: on one page they are two stretches one contact cannot watch; on two
// pages they must hold the same contacts and lead to the same blocks.
void GraphAssembly::compareDrawings(std::uint32_t piece, std::uint32_t reference) {
    const TrackTiles& tiles = graph_.tiles_;
    const std::vector<ContactKey> mine = contactsOf(piece);
    const std::vector<ContactKey> theirs = contactsOf(reference);
    const auto found = std::find_first_of(mine.begin(), mine.end(), theirs.begin(), theirs.end());
    if (found == mine.end())
        return;
    const ContactKey shared = *found;
    const auto tileOf = [&](std::uint32_t p) {
        for (const std::size_t step : pieces_[p].contactSteps)
            if (*tiles.tile(pieces_[p].steps[step].tile).contact == shared)
                return pieces_[p].steps[step].tile;
        return pieces_[p].steps.front().tile;
    };
    const TileId here = tileOf(piece);
    const TileId there = tileOf(reference);
    const std::string contact = "Contact " + std::to_string(shared.number);
    const Block& block = graph_.blocks_[blockOfPiece_[piece]];
    if (pieces_[piece].page(tiles) == pieces_[reference].page(tiles)) {
        problems_.add(
            ProblemKind::ContactInTwoBlocks, here,
            contact + " is drawn here and again at column " + std::to_string(tiles.tile(there).place.column) +
                ", row " + std::to_string(tiles.tile(there).place.row) +
                " of this page, on another stretch of track; one contact can watch only one block, so "
                "both are taken as block '" +
                block.name + "'.");
        return;
    }
    const std::string difference = drawingDifference(piece, reference);
    if (!difference.empty())
        problems_.add(ProblemKind::DrawingsDisagree, here,
                      contact + " is also drawn at " + describePlace(tiles, there) +
                          ", and the drawings differ: " + difference + "; make the pages agree.");
}

// How two drawings of a block on different pages differ: in their contacts (in the block's direction), else
// in what their ends lead to; empty when they agree.
std::string GraphAssembly::drawingDifference(std::uint32_t piece, std::uint32_t reference) const {
    std::vector<ContactKey> mine = contactsOf(piece);
    std::vector<ContactKey> theirs = contactsOf(reference);
    if (flipped_[piece] != flipped_[reference])
        std::reverse(mine.begin(), mine.end());
    if (mine != theirs)
        return "here its block holds contacts " + contactList(mine) + ", there " + contactList(theirs);
    if (neighbours(piece, End::A) == neighbours(reference, End::A) &&
        neighbours(piece, End::B) == neighbours(reference, End::B))
        return {};
    return "here it lies between " + neighbours(piece, End::A) + " and " + neighbours(piece, End::B) +
           ", there between " + neighbours(reference, End::A) + " and " + neighbours(reference, End::B);
}

// What one end of a drawing leads to: the blocks its ways reach, else how the track ends there.
std::string GraphAssembly::neighbours(std::uint32_t piece, End end) const {
    const std::uint8_t side = blockEndOf({piece, 0}).end == end ? 0 : 1;
    std::vector<std::string> names;
    for (const std::uint32_t block : blocksReached({piece, side}))
        names.push_back("'" + graph_.blocks_[block].name + "'");
    if (!names.empty())
        return joined(names, " or ");
    switch (endKindOf(pieces_[piece].ends[side])) {
    case EndKind::BufferStop:
        return "a buffer stop";
    case EndKind::Turntable:
        return "a turntable";
    case EndKind::OpenEnd:
        return "an open end";
    case EndKind::Junction:
    case EndKind::Block:
        break;
    }
    return "no other block";
}

} // namespace stellwerk::trackgraph
