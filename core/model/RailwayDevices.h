#pragma once

#include "model/DeviceBindings.h"
#include "model/Railway.h"

#include <QObject>
#include <QPointer>
#include <functional>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::orccentral {
class OrcSession;
}
namespace stellwerk::romodule {
class RoModuleSession;
}

namespace stellwerk::model {

// The devices as part of the railway (issue 15): accessories bound to an OpenRailCAN decoder output or an
// RO relay are switched there instead of at the CS2, and their position is reported only when the device
// confirmed it (the decoder's acknowledgement, the module's OK) and not reported while it is offline or
// its session is gone; contacts bound to an encoder input or an RO input are lit by the device. The
// track plan, the keyboard and routes see them as they see CS2 articles and S88 contacts. It lives as
// long as the railway and is told the sessions each time the connection makes or tears them down.
class RailwayDevices final : public QObject, public DeviceAccessories {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RailwayDevices)

public:
    RailwayDevices(Railway& railway, DeviceBindings bindings, QObject* parent = nullptr);
    ~RailwayDevices() override;

    // The device sessions there are now (null / none: gone). Switchings still waiting fail.
    void setSessions(orccentral::OrcSession* orc, const std::vector<romodule::RoModuleSession*>& modules);
    const DeviceBindings& bindings() const { return bindings_; }
    // Other bindings (the Devices panel's editor): an item no longer bound is no longer reported (the
    // station has not said where it stands), and its switchings waiting for a device fail.
    void setBindings(DeviceBindings bindings);

    bool drives(std::int64_t accessory) const override;
    bool lights(ContactKey contact) const override;
    void switchTo(std::int64_t accessory, int position, std::function<void(const QString&)> done) override;

signals:
    void bindingsChanged();

private:
    struct Pending {
        std::int64_t accessory = 0;
        int position = 0;
        std::function<void(const QString&)> done;
        QPointer<QObject> session; // the session it waits for
    };

    QString switchRelay(const RoRelay& relay, int position);
    QString switchOrc(const OrcOutput& output, int position);
    void watchOrc();
    void watchModule(romodule::RoModuleSession* module);
    void orcDeviceChanged(std::uint32_t uid);
    void orcSwitched(std::uint16_t target, std::uint8_t position, bool confirmed);
    void orcInputs(std::uint16_t encoder, std::uint32_t inputs);
    void moduleOutputs(const QString& module, std::uint32_t outputs);
    void moduleFailed(const QString& module, std::uint32_t relays, const QString& why);
    void moduleInputs(const QString& module, std::uint32_t inputs);
    void refresh();
    std::optional<int> orcPosition(const OrcOutput& output) const;
    std::optional<int> relayPosition(const RoRelay& relay) const;
    std::optional<bool> orcInput(const OrcInput& input) const;
    std::optional<bool> roInput(const RoInput& input) const;
    void finish(const std::function<bool(const Pending&)>& which, const QString& failure);
    bool holds(const QObject* session) const;
    romodule::RoModuleSession* module(const QString& name) const;

    Railway& railway_;
    DeviceBindings bindings_;
    QPointer<orccentral::OrcSession> orc_;
    std::vector<QPointer<romodule::RoModuleSession>> modules_;
    std::map<std::uint16_t, std::uint8_t> decoderPositions_; // Pos each decoder confirmed, by Ziel-Id
    std::vector<Pending> pending_;
};

} // namespace stellwerk::model
