#pragma once

#include <QObject>
#include <QRandomGenerator>
#include <QTimer>
#include <chrono>

namespace stellwerk::sim {

class SimulatedMs1;

// Someone holding an MS1 who drives now and then (for stellwerk-sim and the demo): while the handheld may
// drive its locomotive, every period the knob goes to a new speed between 0 and 60, and now and then f0 is
// switched. Random, but the same for the same UID, so that a run can be repeated.
class Ms1Driver : public QObject {
    Q_OBJECT

public:
    Ms1Driver(SimulatedMs1& ms1, std::chrono::milliseconds period, QObject* parent = nullptr);

private:
    void drive();

    SimulatedMs1& ms1_;
    QTimer timer_;
    QRandomGenerator random_;
};

} // namespace stellwerk::sim
