#pragma once

namespace stellwerk::ui {

// Whether the track plan shows its blocks, their names and the drawing's problems (key trackPlan/blocks),
// kept from one run to the next.
class BlockViewSettings final {
public:
    static bool shown();
    static void setShown(bool shown);
};

} // namespace stellwerk::ui
