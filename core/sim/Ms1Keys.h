#pragma once

#include "sim/Ms1Memory.h"

#include <cstddef>

namespace stellwerk::sim {

// The MS1's keys and knob as frames to its master (document 7.3, 7.4, 7.6): take a locomotive of the
// stack, choose the shown one again, turn the knob (speed 0..127 and direction), a function key, the stop
// and go keys. Each returns false, sending nothing, where the handheld could not do it (no such locomotive
// or function, or a locomotive it may not drive).
class Ms1Keys {
public:
    explicit Ms1Keys(Ms1Memory& memory) : memory_(memory) {}

    // Take request, priority 101: `03 00 00 08 00 01` (trace #92); the master's echo grants it.
    bool take(std::size_t stackIndex, Ms1Outbox& out);
    // The shown locomotive chosen again (`03 01 00 08 00 01`), after the master released it.
    bool chooseAgain(Ms1Outbox& out);
    // FKT 1 with priority 010 ("Slave fährt Lok"): the speed, bit 7 for reverse. Not acknowledged, so the
    // MS1 shows it at once.
    bool drive(int speed, bool reverse, Ms1Outbox& out);
    // FKT n+2 for function fn, 1 = on / pressed.
    bool function(int number, bool on, Ms1Outbox& out);
    // The stop key (`01 00 01` on the SY handle) or go (`01 00 00`, notes B§3.3); the MS1 shows stop only
    // when the master says so.
    bool stopKey(bool stop, Ms1Outbox& out);

private:
    bool throttle(std::uint8_t control, Ms1Outbox& out);
    Ms1Loco* drivable();

    Ms1Memory& memory_;
};

} // namespace stellwerk::sim
