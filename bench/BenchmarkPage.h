#pragma once

#include "cs2config/TrackElement.h"
#include "cs2config/TrackElementType.h"

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

} // namespace stellwerk::bench
