#pragma once

#include "model/DeviceBindings.h"
#include "model/RailwayDevices.h"
#include "model/RailwayThrottles.h"

#include <QObject>
#include <QPointer>
#include <functional>
#include <vector>

namespace stellwerk::connection {
class StationConnection;
}
namespace stellwerk::mcanhandhelds {
class HandheldMaster;
}
namespace stellwerk::model {
class LayoutInUse;
class Railway;
} // namespace stellwerk::model
namespace stellwerk::orccentral {
class OrcSession;
}
namespace stellwerk::romodule {
class RoModuleSession;
}
namespace stellwerk::station {
class StationSession;
struct StartupResult;
} // namespace stellwerk::station

namespace stellwerk::binding {

// The one place where the railway is bound to the sessions, for the window and the command line alike: a
// new Railway for every session (made before its start-up runs, so that it keeps the start-up's state
// answers) with the MS1 handhelds driving it; loaded, and the layout in use set from the station's
// download, whenever a start-up finishes; the accessories and contacts of devices and the OpenRailCAN
// throttles bound again whenever the device sessions change; gone before its session goes. Given a
// StationConnection it follows it; a command that runs its session itself tells it what happens.
class RailwayBinding final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RailwayBinding)

public:
    // `layout` (may be null, else it must outlive the binding) is set from each station's download, which
    // it forgets again when the session ends or the binding goes.
    explicit RailwayBinding(model::LayoutInUse* layout = nullptr, QObject* parent = nullptr);
    // Follows `connection`, which must outlive the binding: its sessions, start-ups and device sessions;
    // the pictures of an opened layout go to its LocomotivePictures.
    explicit RailwayBinding(connection::StationConnection& connection, model::LayoutInUse* layout = nullptr,
                            QObject* parent = nullptr);
    ~RailwayBinding() override;

    // The railway of the current session, or null while there is none.
    model::Railway* railway() const { return railway_; }
    // What binds the railway's accessories and contacts to the devices (null until bindDevices()).
    model::RailwayDevices* devices() const { return devices_; }
    // From now on the railway's accessories and contacts are bound to the device sessions with the
    // bindings `bindingsOf` gives (asked again for every railway: they may have changed), and the
    // OpenRailCAN throttles drive it. Without it the railway is bound to the handhelds only.
    void bindDevices(std::function<model::DeviceBindings()> bindingsOf);

    // What happens to a session, for a caller that runs it itself (the connection's signals do this):
    // a session started (`handhelds`: its MS1 master, or null), its start-up finished, it went away, and
    // the device sessions that are open now.
    void sessionStarted(station::StationSession& session, mcanhandhelds::HandheldMaster* handhelds);
    void configurationLoaded(const station::StartupResult& result);
    void sessionEnded();
    void devicesChanged(orccentral::OrcSession* orc, const std::vector<romodule::RoModuleSession*>& modules);

signals:
    // A new railway (or null); the previous one is deleted right after this signal.
    void railwayChanged(stellwerk::model::Railway* railway);

private:
    void follow();
    void followDevices();
    void bindDevicesOf(model::Railway& railway);
    void replace(model::Railway* railway);
    static void retire(model::Railway* railway);

    connection::StationConnection* connection_ = nullptr;
    model::LayoutInUse* layout_ = nullptr;
    model::Railway* railway_ = nullptr;
    std::function<model::DeviceBindings()> bindingsOf_;
    QPointer<model::RailwayDevices> devices_;
    QPointer<model::RailwayThrottles> throttles_;
    orccentral::OrcSession* orc_ = nullptr;
    std::vector<romodule::RoModuleSession*> modules_;
};

} // namespace stellwerk::binding
