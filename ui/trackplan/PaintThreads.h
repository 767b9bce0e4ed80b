#pragma once

#include <cstddef>
#include <functional>

namespace stellwerk::ui {

// The threads that help the GUI thread paint a page: drawing the pictures of hundreds of tiles and
// filling a large area take a fraction of the time on all cores. The threads are kept, not started per
// paint: a new thread also starts with new memory, and touching new memory is what a first paint spends
// most on.
class PaintThreads final {
public:
    // How many threads a paint may use, this one included: the machine's cores, at most four.
    static std::size_t count();
    // Calls work(0) .. work(parts - 1), work(0) on this thread and the others on the kept helpers at the
    // same time; returns when every part is done.
    static void run(std::size_t parts, const std::function<void(std::size_t part)>& work);
};

} // namespace stellwerk::ui
