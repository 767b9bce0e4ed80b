#pragma once

#include "cs2config/TrackElement.h"
#include "cs2config/TrackElementType.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stellwerk::bench {

// The benchmarks' 2,000-tile page: 50 x 40 tiles cycling through every element type and rotation, named
// "Gleis" (as when the figures of issue 13 were taken) or each with a name of its own (every name laid out
// anew: the worst for drawing). Used by the track plan's and the track graph's benchmarks.
inline std::vector<cs2config::TrackElement> benchmarkPage(bool ownNames) {
    std::vector<cs2config::TrackElement> elements;
    const auto types = cs2config::trackElementTypes();
    for (int i = 0; i < 2000; ++i) {
        cs2config::TrackElement element;
        element.position = {0, std::uint8_t(i % 50), std::uint8_t(i / 50)};
        element.type = std::string(types[std::size_t(i) % types.size()].name);
        element.rotation = (i / int(types.size())) % 4;
        element.text = ownNames ? "W" + std::to_string(i + 1) : "Gleis";
        elements.push_back(element);
    }
    return elements;
}

// A station of 2,000 tiles (many blocks, turnouts and ways): rows 0..9 of 200 tiles, buffer stops at both
// ends, contacts at columns ending in 2, signals at columns ending in 7 (facing alternately), crossovers
// between rows r and r + 1 every 20 columns.
inline std::vector<cs2config::TrackElement> stationPage() {
    std::vector<cs2config::TrackElement> elements;
    const auto place = [&elements](int column, int row, const char* type, int rotation,
                                   std::int64_t article) {
        cs2config::TrackElement element;
        element.position = {0, std::uint8_t(column), std::uint8_t(row)};
        element.type = type;
        element.rotation = rotation;
        element.article = article;
        elements.push_back(element);
    };
    for (int row = 0; row < 10; ++row)
        for (int column = 0; column < 200; ++column) {
            const bool down = row < 9 && column % 20 == 10 + 5 * (row % 2);     // crossover to the row below
            const bool up = row > 0 && column % 20 == 10 + 5 * ((row - 1) % 2); // and from the row above
            const std::int64_t keyboard = 1 + row * 20 + column / 10;
            if (column == 0 || column == 199)
                place(column, row, "prellbock", column == 0 ? 2 : 0, -1);
            else if (down)
                place(column, row, "rechtsweiche", 3, 2 * keyboard);
            else if (up)
                place(column, row, "rechtsweiche", 1, 2 * (keyboard - 20));
            else if (column % 10 == 2)
                place(column, row, "s88kontakt", 0, 1000 + row * 200 + column);
            else if (column % 10 == 7)
                place(column, row, "signal", (column / 10) % 2 * 2, 2 * (500 + row * 20 + column / 10));
            else
                place(column, row, "gerade", 0, -1);
        }
    return elements;
}

} // namespace stellwerk::bench
