#pragma once

#include "mcanhandhelds/HandheldRailway.h"

#include <QObject>

namespace stellwerk::mcanhandhelds {
class HandheldMaster;
}

namespace stellwerk::model {

class Railway;

// The railway as the MS1 handhelds drive it: their master's view of this Railway (its locomotives from
// lokomotive.cs2, how they run as the station confirmed, the track power), their intents carried out as the
// app's throttles do (commands to the station), and the railway's changes told to the master. It lives as
// long as the railway, and leaves the master without a railway when it goes.
class RailwayHandhelds final : public QObject, public mcanhandhelds::HandheldRailway {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RailwayHandhelds)

public:
    RailwayHandhelds(Railway& railway, mcanhandhelds::HandheldMaster& master, QObject* parent = nullptr);
    ~RailwayHandhelds() override;

    std::vector<mcanhandhelds::HandheldLoco> locomotives() const override;
    std::optional<mcanhandhelds::LocoDrive> drive(std::uint32_t locId) const override;
    std::optional<bool> powerOn() const override;
    void setSpeed(std::uint32_t locId, int speed) override;
    void setDirection(std::uint32_t locId, bool forward) override;
    void setFunction(std::uint32_t locId, int function, bool on) override;
    void setPower(bool on) override;

private:
    mcanhandhelds::LocoKind kindOf(std::uint32_t locId) const;

    Railway& railway_;
    mcanhandhelds::HandheldMaster& master_;
};

} // namespace stellwerk::model
