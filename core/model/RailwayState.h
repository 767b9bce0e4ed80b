#pragma once

#include "cs2config/RouteFile.h"
#include "model/Accessory.h"
#include "model/Device.h"
#include "model/FeedbackContact.h"
#include "model/Locomotive.h"
#include "model/Registry.h"
#include "model/Route.h"
#include "model/TrackLayout.h"
#include "station/StartupSequence.h"
#include "station/StationUpdates.h"

#include <QDateTime>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace stellwerk::model {

// What one batch of station updates changed, each item once: the Railway turns it into one signal
// per kind.
struct RailwayChanges {
    ChangedKeys<std::uint32_t> locomotives;
    ChangedKeys<std::int64_t> accessories;
    // Keyboard numbers (MM2) without an article whose position the bus showed.
    ChangedKeys<std::int64_t> addresses;
    ChangedKeys<ContactKey> contacts;
    ChangedKeys<std::uint32_t> devices;
    std::optional<station::PowerState> power;
    std::vector<station::OverloadReport> overloads;
    bool configurationChanged = false;
};

// Everything the UI shows about the layout, updated only from what the station confirmed or the bus
// showed. Plain data without signals, so that applying a batch is one call and easy to test.
class RailwayState {
public:
    // Builds the layout from the start-up's files and devices; state the bus already reported (a
    // Railway created before the start-up sees the state answers) is kept.
    void load(const station::StartupResult& startup);
    RailwayChanges apply(const station::StationUpdates& updates, const QDateTime& now);
    // Who is on a contact (FeedbackContact::occupant); a contact not reported yet is made for it.
    RailwayChanges setOccupant(ContactKey key, std::uint32_t locId);
    // What a device (not the station) reported of an accessory or a contact; nullopt: not reported any
    // more. A contact not known yet is made for it.
    RailwayChanges reportDevicePosition(std::int64_t accessory, std::optional<int> position);
    RailwayChanges reportDeviceContact(ContactKey key, std::optional<bool> occupied, const QDateTime& now);

    Registry<std::uint32_t, Locomotive>& locomotives() { return locomotives_; }
    const Registry<std::uint32_t, Locomotive>& locomotives() const { return locomotives_; }
    const Registry<std::int64_t, Accessory>& accessories() const { return accessories_; }
    const Registry<ContactKey, FeedbackContact>& contacts() const { return contacts_; }
    const Registry<std::int64_t, Route>& routes() const { return routes_; }
    Registry<std::int64_t, Route>& routes() { return routes_; }
    const cs2config::RouteFile& routeFile() const { return routeFile_; }
    // lokomotive.cs2 as the station sent it (or as last edited), null when the station sent none.
    const cs2config::LocomotiveFile* locomotiveFile() const {
        return locomotiveFile_ ? &*locomotiveFile_ : nullptr;
    }
    // Takes an edited lokomotive.cs2: the locomotives follow it, keeping the states the bus confirmed.
    void replaceLocomotiveFile(const cs2config::LocomotiveFile& file);
    const Registry<std::uint32_t, Device>& devices() const { return devices_; }
    Registry<std::uint32_t, Device>& devices() { return devices_; }
    const TrackLayout& layout() const { return layout_; }
    std::optional<station::PowerState> power() const { return power_; }
    // The power state is no longer known (the station went silent or the connection was lost).
    void forgetPower() { power_.reset(); }
    // Nothing shown is reported any more: power unknown, and every locomotive value, accessory position
    // and contact "not reported" until the station reports it again. Keyboard addresses are forgotten.
    void forgetReported();
    // The position last seen on the bus for an MM2 keyboard number that no article uses.
    std::optional<int> addressPosition(std::int64_t address) const;

private:
    void loadLocomotives(const std::optional<cs2config::LocomotiveFile>& file);
    void loadAccessories(const station::StartupResult& startup);
    void loadContacts();
    void loadDevices(const station::StartupResult& startup);
    void applyLocomotives(const station::StationUpdates& updates, RailwayChanges& changes);
    void applyAccessories(const station::StationUpdates& updates, RailwayChanges& changes);
    void applyLooseAddress(const station::AccessoryChange& change, RailwayChanges& changes);
    void applyContacts(const station::StationUpdates& updates, const QDateTime& now, RailwayChanges& changes);
    void applyDevices(const station::StationUpdates& updates, const QDateTime& now, RailwayChanges& changes);
    Locomotive& locomotive(cs2::LocId id);

    // Which accessory (keyboard id) and which of its addresses a wire address belongs to.
    struct AddressOwner {
        std::int64_t accessory = 0;
        int addressIndex = 0;
    };

    Registry<std::uint32_t, Locomotive> locomotives_;
    Registry<std::int64_t, Accessory> accessories_;
    std::unordered_map<std::uint32_t, AddressOwner> addressOwners_;
    std::unordered_map<std::int64_t, int> addressPositions_;
    Registry<ContactKey, FeedbackContact> contacts_;
    Registry<std::int64_t, Route> routes_;
    cs2config::RouteFile routeFile_;
    std::optional<cs2config::LocomotiveFile> locomotiveFile_;
    Registry<std::uint32_t, Device> devices_;
    TrackLayout layout_;
    std::optional<station::PowerState> power_;
};

} // namespace stellwerk::model
