#pragma once

#include "can/CanFrame.h"
#include "mcanhandhelds/HandheldBook.h"
#include "mcanhandhelds/HandheldMaster.h"
#include "mcanhandhelds/HandheldRailway.h"

#include <QObject>
#include <memory>
#include <vector>

namespace stellwerk::sim {

class SimulatedStation;

// The simulated CS2 as the M-CAN master of the MS1 handhelds on its bus, as a real CS2 is: a peer on the
// simulated bus that answers the handhelds with Stellwerk's master, and carries out what they do inside the
// station, as its own commands; what the station then reports on the bus (theirs, and other controllers'
// changes) reaches the handhelds that show it. A SimulatedBus peer: receive() and framesEmitted.
class StationHandhelds final : public QObject, private mcanhandhelds::HandheldRailway {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(StationHandhelds)

public:
    explicit StationHandhelds(SimulatedStation& station, mcanhandhelds::MasterSettings settings = {},
                              QObject* parent = nullptr);
    ~StationHandhelds() override;

    // A frame on the bus: M-CAN goes to the master; the station's CS2 reports tell it what changed.
    void receive(const can::CanFrame& frame);
    const mcanhandhelds::HandheldMaster& master() const { return *master_; }
    mcanhandhelds::HandheldMaster& master() { return *master_; }

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);

private:
    std::vector<mcanhandhelds::HandheldLoco> locomotives() const override;
    std::optional<mcanhandhelds::LocoDrive> drive(std::uint32_t locId) const override;
    std::optional<bool> powerOn() const override;
    void setSpeed(std::uint32_t locId, int speed) override;
    void setDirection(std::uint32_t locId, bool forward) override;
    void setFunction(std::uint32_t locId, int function, bool on) override;
    void setPower(bool on) override;
    void command(can::CanFrame frame);
    void observe(const can::CanFrame& frame);

    SimulatedStation& station_;
    mcanhandhelds::MemoryHandheldBook book_;
    std::unique_ptr<mcanhandhelds::HandheldMaster> master_;
    std::uint16_t hash_;
};

} // namespace stellwerk::sim
