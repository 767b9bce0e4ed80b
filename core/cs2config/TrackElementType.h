#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace stellwerk::cs2config {

// What a tile is for a renderer and a turnout panel, independent of its exact `.typ` word.
enum class TrackCategory : std::uint8_t {
    Empty,         // leer
    Track,         // plain track: straight, curve, crossing, buffer stop, tunnel...
    Turnout,       // points and slips
    Signal,        // light and semaphore signals
    Feedback,      // s88 contact tiles
    RouteButton,   // starts a route (fahrstrasse)
    PageLink,      // arrow to another page (pfeil)
    Text,          // a label
    Uncoupler,     // uncoupling track
    Output,        // a plain decoder output: lamp, level crossing, k84 relay
    Turntable,     // turntable tiles
    TransferTable, // transfer table tiles (Schiebebühne)
    Unknown,       // a `.typ` we do not know; kept as read
};

// What the number in an element's `.artikel` refers to.
enum class ArticleLink : std::uint8_t {
    None,            // plain track: `.artikel=-1`
    Accessory,       // an article of magnetartikel.cs2 (see the field notes for the numbering)
    FeedbackContact, // an s88 contact number, with `.deviceId` for the feedback device
    Route,           // a route of fahrstrassen.cs2
    Page,            // another track plan page
};

// One known `.typ` word with its meaning; the table lists every type of the document (8.3.5) and the
// ones real CS2/CS3 firmware writes that the document leaves out.
struct TrackElementType {
    std::string_view name;
    TrackCategory category;
    ArticleLink article;
    bool documented; // listed in the document's chapter 8.3.5

    // True when clicking the tile switches an accessory (turnout, signal, uncoupler, output...).
    bool switchable() const { return article == ArticleLink::Accessory; }
};

std::span<const TrackElementType> trackElementTypes();
// The type with this `.typ` word; null for words we do not know.
const TrackElementType* findTrackElementType(std::string_view name);
// "track", "turnout", ... for JSON and messages.
std::string_view trackCategoryName(TrackCategory category);
std::string_view articleLinkName(ArticleLink link);

} // namespace stellwerk::cs2config
