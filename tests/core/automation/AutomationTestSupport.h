#pragma once

// The demo layout's track graph, read as the layout in use (model::LayoutInUse, as the command line opens
// --layout), and its blocks by name: 1 Gleis 2 (contact 2), 2 Abstellgleis (9), 3 Einfahrt West (7), 4 Gleis
// 1 (1), 5 Ausfahrt Ost (8), 6 Block 1 (3), 7 Block 2 (4), 8 Block 3 (5), 9 Block 4 (6).

#include "model/LayoutInUse.h"

#include <gtest/gtest.h>
#include <memory>

namespace stellwerk::automation::test {

inline const trackgraph::TrackGraph& demo() {
    static const std::shared_ptr<const trackgraph::TrackGraph> graph = [] {
        model::LayoutInUse layout;
        EXPECT_EQ(layout.open(STELLWERK_DEMO_LAYOUT_DIR), "");
        return layout.graph() ? layout.graph() : std::make_shared<const trackgraph::TrackGraph>();
    }();
    return *graph;
}

enum DemoBlock : int {
    Gleis2 = 1,
    Abstellgleis = 2,
    EinfahrtWest = 3,
    Gleis1 = 4,
    AusfahrtOst = 5,
    Block1 = 6,
    Block2 = 7,
    Block3 = 8,
    Block4 = 9,
};

inline trackgraph::ContactKey contact(std::int64_t number) {
    return {0, number};
}

} // namespace stellwerk::automation::test
