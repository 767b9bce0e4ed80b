#pragma once

#include "orccentral/ThrottleBridge.h"

#include <QObject>
#include <QPointer>

namespace stellwerk::orccentral {
class OrcSession;
}

namespace stellwerk::model {

class Railway;

// The railway as OpenRailCAN throttles drive it (issue 15): the ThrottleBridge's view of this Railway, its
// intents carried out as the app's own throttles and the MS1 handhelds' are (commands to the station through
// the railway, which never sends later what it gave up on), and the locos' state as the station confirmed
// it. It lives as long as the railway and is told the central each time the connection makes or tears it
// down; the bridge lives beside that central.
class RailwayThrottles final : public QObject, public orccentral::ThrottleRailway {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RailwayThrottles)

public:
    explicit RailwayThrottles(Railway& railway, QObject* parent = nullptr);
    ~RailwayThrottles() override;

    // The OpenRailCAN central there is now (null: gone); the throttles on its bus drive the railway.
    void setSession(orccentral::OrcSession* orc);
    const orccentral::ThrottleBridge* bridge() const { return bridge_.data(); }

    std::optional<orccentral::LocoState> loco(std::uint32_t locId) const override;
    void setSpeed(std::uint32_t locId, int speed) override;
    void setDirection(std::uint32_t locId, bool forward) override;
    void setFunction(std::uint32_t locId, int function, bool on) override;
    void emergencyStop(std::uint32_t locId) override;
    void stopAll() override;

private:
    Railway& railway_;
    QPointer<orccentral::ThrottleBridge> bridge_; // a child of the central, gone with it
};

} // namespace stellwerk::model
