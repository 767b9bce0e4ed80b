#pragma once

#include <QList>
#include <cstdint>

namespace stellwerk::ui {

// Which locomotives the open throttles drive, left to right (0: a throttle without one), remembered
// between runs under throttles/locomotives.
class ThrottleSettings final {
public:
    static constexpr int MaximumThrottles = 9; // one per Alt+1..Alt+9

    static QList<std::uint32_t> load();
    static void save(const QList<std::uint32_t>& locomotives);
};

} // namespace stellwerk::ui
