#include "sim/Ms1Driver.h"

#include "sim/SimulatedMs1.h"

namespace stellwerk::sim {

namespace {

constexpr int TopSpeed = 60;   // of 127: a calm pace for a demo
constexpr int LightsEvery = 4; // one turn in four switches f0
constexpr int Headlights = 0;  // f0

} // namespace

Ms1Driver::Ms1Driver(SimulatedMs1& ms1, std::chrono::milliseconds period, QObject* parent)
    : QObject(parent), ms1_(ms1), random_(ms1.identity().uid) {
    connect(&timer_, &QTimer::timeout, this, &Ms1Driver::drive);
    timer_.start(period);
}

void Ms1Driver::drive() {
    const Ms1Loco* loco = ms1_.shownLoco();
    if (!loco || ms1_.memory().control != Ms1Control::Granted)
        return;
    const auto direction =
        loco->reverse ? SimulatedMs1::Direction::Reverse : SimulatedMs1::Direction::Forward;
    const bool lightsOn = !loco->functions.empty() && loco->functions[Headlights].value != 0;
    const bool hasLights = !loco->functions.empty();
    ms1_.setSpeed(random_.bounded(TopSpeed + 1), direction);
    if (hasLights && random_.bounded(LightsEvery) == 0)
        ms1_.setFunction(Headlights, !lightsOn);
}

} // namespace stellwerk::sim
