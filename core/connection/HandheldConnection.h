#pragma once

#include "mcanhandhelds/HandheldMaster.h"

#include <QObject>
#include <QString>
#include <memory>
#include <vector>

namespace stellwerk::bus {
class Bus;
}
namespace stellwerk::station {
struct DeviceDescription;
}

namespace stellwerk::connection {

// Whether Stellwerk answers the MS1 handhelds on the station's bus (M-CAN): automatically, unless a Central
// Station is there (it is their master itself); always; or never (it only watches).
enum class HandheldRole : std::uint8_t { Automatic, Master, Watch };

struct HandheldSettings {
    HandheldRole role = HandheldRole::Automatic;
    mcanhandhelds::MasterSettings master{};
    mcanhandhelds::HandheldBook* book =
        nullptr; // where stacks and names are kept (not owned); null: not kept
};

// Stellwerk's part in the handhelds' conversation on the station's bus: the M-CAN master fed the bus's
// M-CAN frames and sending on its transport. In Automatic it only watches until the start-up has listed
// the devices, and stays a watcher when a Central Station is among them; another master speaking makes it
// fall silent in any role.
class HandheldConnection final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(HandheldConnection)

public:
    HandheldConnection(bus::Bus& bus, const HandheldSettings& settings, QObject* parent = nullptr);
    ~HandheldConnection() override;

    mcanhandhelds::HandheldMaster& master() { return *master_; }
    HandheldRole role() const { return role_; }
    // The devices the start-up found: decides the Automatic role.
    void devicesListed(const std::vector<station::DeviceDescription>& devices);
    // A new role from now on; `devices` are the ones the last start-up found (none yet: empty).
    void setRole(HandheldRole role, const std::vector<station::DeviceDescription>& devices);

private:
    void applyRole();

    HandheldRole role_;
    bool centralStation_ = false; // a Central Station answered the last start-up's ping
    bool devicesKnown_ = false;
    std::unique_ptr<mcanhandhelds::HandheldMaster> master_;
};

} // namespace stellwerk::connection
