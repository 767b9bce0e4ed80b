#pragma once

namespace stellwerk::automation {

// The speeds an automatic train runs at, in the station's speed steps (0..1000), and what a step means on
// the track: speed s runs s / 1000 * 500 mm/s, i.e. 0.5 mm/s per step, the mapping the simulator moves
// its trains by (sim::TrainMovement::Options::topSpeedMmPerSecond). A block with one contact is left at
// the distance this mapping gives.
struct SpeedProfile {
    int travel = 500; // 250 mm/s
    int creep = 150;  // 75 mm/s, from the braking contact (or the last CreepMm before the stop)
    int topSpeedMmPerSecond = 500;

    double mmPerSecond(int speed) const { return speed * double(topSpeedMmPerSecond) / 1000.0; }
};

} // namespace stellwerk::automation
