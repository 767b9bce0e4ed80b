#include "automation/Placement.h"

#include "cs2/LocIdText.h"

#include <charconv>

namespace stellwerk::automation {

Expected<Placement, std::string> parsePlacement(std::string_view text) {
    const std::size_t equals = text.find('=');
    if (equals == std::string_view::npos)
        return "'" + std::string(text) + "' is not LOC=CONTACT[:END] (e.g. mfx:5=12:a)";
    const auto loco = cs2::parseLocomotive(text.substr(0, equals));
    if (!loco)
        return loco.error();
    Placement placement{loco->value(), 0, trackgraph::End::B};
    std::string_view place = text.substr(equals + 1);
    if (const std::size_t colon = place.find(':'); colon != std::string_view::npos) {
        const std::string_view end = place.substr(colon + 1);
        if (end != "a" && end != "b")
            return "the end '" + std::string(end) + "' is not a or b";
        placement.towards = end == "a" ? trackgraph::End::A : trackgraph::End::B;
        place = place.substr(0, colon);
    }
    const auto [last, error] = std::from_chars(place.data(), place.data() + place.size(), placement.contact);
    if (error != std::errc() || last != place.data() + place.size() || place.empty() || placement.contact < 1)
        return "the contact '" + std::string(place) + "' is not a contact number";
    return placement;
}

} // namespace stellwerk::automation
