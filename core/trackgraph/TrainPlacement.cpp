#include "trackgraph/TrainPlacement.h"

#include "cs2/LocIdText.h"

#include <charconv>
#include <optional>

namespace stellwerk::trackgraph {

namespace {

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

Expected<End, std::string> endNamed(std::string_view text) {
    if (text == "a" || text == "A")
        return End::A;
    if (text == "b" || text == "B")
        return End::B;
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
    TrainPlacement placement{loco->value(), 0, End::B};
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

} // namespace stellwerk::trackgraph
