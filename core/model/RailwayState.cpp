#include "model/RailwayState.h"

namespace stellwerk::model {

void RailwayState::load(const station::StartupResult& startup) {
    loadLocomotives(startup.locomotives);
    loadAccessories(startup);
    routeFile_ = startup.routes.value_or(cs2config::RouteFile{});
    routes_.clear();
    for (const cs2config::Route& route : routeFile_.routes)
        routes_.put(route.id, Route(route));
    layout_ = TrackLayout(startup.pages);
    loadContacts();
    loadDevices(startup);
}

void RailwayState::forgetReported() {
    power_.reset();
    for (Locomotive& loco : locomotives_.items())
        loco.forgetReported();
    for (Accessory& accessory : accessories_.items())
        accessory.forgetReported();
    for (FeedbackContact& contact : contacts_.items())
        contact.forgetReported();
    addressPositions_.clear();
}

void RailwayState::replaceLocomotiveFile(const cs2config::LocomotiveFile& file) {
    // A locomotive that left the file goes; one only the bus showed stays, as after a start-up.
    Registry<std::uint32_t, Locomotive> kept;
    for (const Locomotive& loco : locomotives_.items())
        if (!loco.inLayout() || file.find(loco.id().value()))
            kept.put(loco.id().value(), loco);
    locomotives_ = std::move(kept);
    loadLocomotives(file);
}

void RailwayState::loadLocomotives(const std::optional<cs2config::LocomotiveFile>& file) {
    locomotiveFile_ = file;
    Registry<std::uint32_t, Locomotive> seen = std::move(locomotives_);
    locomotives_.clear();
    if (file)
        for (const cs2config::Locomotive& record : file->locomotives) {
            if (record.isEmpty())
                continue;
            Locomotive& loco = locomotives_.put(record.uid, Locomotive::fromFile(record));
            if (const Locomotive* before = seen.find(record.uid))
                loco.keepConfirmedState(*before);
        }
    for (const Locomotive& loco : seen.items())
        if (!locomotives_.find(loco.id().value()))
            locomotives_.put(loco.id().value(), loco);
}

void RailwayState::loadAccessories(const station::StartupResult& startup) {
    accessories_.clear();
    addressOwners_.clear();
    if (!startup.accessories)
        return;
    for (const cs2config::Accessory& record : startup.accessories->accessories) {
        if (record.id < 1 || record.secondOutput)
            continue; // no address, or the second half of a pair that shares the first one's id
        const Accessory& accessory = accessories_.put(record.id, Accessory::fromFile(record));
        for (int n = 0; n < accessory.addressCount(); ++n)
            if (const auto address = accessory.address(n))
                addressOwners_.emplace(address->value(), AddressOwner{record.id, n});
    }
}

void RailwayState::loadContacts() {
    Registry<ContactKey, FeedbackContact> seen = std::move(contacts_);
    contacts_.clear();
    for (FeedbackContact contact : layout_.contacts()) {
        if (const FeedbackContact* before = seen.find(contact.key())) {
            const QString name = contact.name();
            contact = *before;
            contact.setName(name);
        }
        contacts_.put(contact.key(), contact);
    }
    for (const FeedbackContact& contact : seen.items())
        if (!contacts_.find(contact.key()))
            contacts_.put(contact.key(), contact);
}

void RailwayState::loadDevices(const station::StartupResult& startup) {
    for (const station::DeviceDescription& description : startup.devices)
        devices_.put(description.identity.uid, Device(description));
}

RailwayChanges RailwayState::apply(const station::StationUpdates& updates, const QDateTime& now) {
    RailwayChanges changes;
    applyDevices(updates, now, changes);
    applyLocomotives(updates, changes);
    applyAccessories(updates, changes);
    applyContacts(updates, now, changes);
    for (const station::PowerChange& change : updates.power)
        if (power_ != change.state)
            changes.power = power_ = change.state;
    changes.overloads = updates.overloads;
    changes.configurationChanged = updates.configurationChanged;
    return changes;
}

Locomotive& RailwayState::locomotive(cs2::LocId id) {
    if (Locomotive* loco = locomotives_.find(id.value()))
        return *loco;
    return locomotives_.put(id.value(), Locomotive(id));
}

// Directions before speeds: a batch that turns a locomotive and then starts it ends with the new speed.
void RailwayState::applyLocomotives(const station::StationUpdates& updates, RailwayChanges& changes) {
    for (const station::LocomotiveDirectionChange& change : updates.directions)
        if (locomotive(change.loco).confirmDirection(change.direction))
            changes.locomotives.add(change.loco.value());
    for (const station::LocomotiveSpeedChange& change : updates.speeds)
        if (locomotive(change.loco).confirmSpeed(change.speed))
            changes.locomotives.add(change.loco.value());
    for (const station::LocomotiveFunctionChange& change : updates.functions)
        if (locomotive(change.loco).confirmFunction(change.function, change.value != 0))
            changes.locomotives.add(change.loco.value());
}

void RailwayState::applyAccessories(const station::StationUpdates& updates, RailwayChanges& changes) {
    for (const station::AccessoryChange& change : updates.accessories) {
        if (change.current == 0)
            continue; // switching the output off keeps the position
        const auto owner = addressOwners_.find(change.article.value());
        if (owner == addressOwners_.end()) {
            applyLooseAddress(change, changes);
            continue;
        }
        Accessory* accessory = accessories_.find(owner->second.accessory);
        if (accessory->confirmPosition(accessory->positionOf(owner->second.addressIndex, change.position)))
            changes.accessories.add(accessory->id());
    }
}

// A keyboard address without an article: its position is kept for the keyboard's plain buttons.
void RailwayState::applyLooseAddress(const station::AccessoryChange& change, RailwayChanges& changes) {
    if (change.article.protocol() != cs2::Protocol::Mm2Accessory)
        return;
    const auto address = std::int64_t(change.article.address());
    auto [it, added] = addressPositions_.try_emplace(address, change.position);
    if (added || it->second != change.position) {
        it->second = change.position;
        changes.addresses.add(address);
    }
}

std::optional<int> RailwayState::addressPosition(std::int64_t address) const {
    const auto it = addressPositions_.find(address);
    return it == addressPositions_.end() ? std::nullopt : std::optional<int>(it->second);
}

void RailwayState::applyContacts(const station::StationUpdates& updates, const QDateTime& now,
                                 RailwayChanges& changes) {
    for (const station::FeedbackContactChange& change : updates.contacts) {
        const ContactKey key = contactKey(change.device, change.contact);
        FeedbackContact* contact = contacts_.find(key);
        if (!contact)
            contact = &contacts_.put(key, FeedbackContact(change.device, change.contact));
        if (contact->confirm(change.occupied, now))
            changes.contacts.add(key);
    }
}

RailwayChanges RailwayState::setOccupant(ContactKey key, std::uint32_t locId) {
    RailwayChanges changes;
    FeedbackContact* contact = contacts_.find(key);
    if (!contact)
        contact = &contacts_.put(key, FeedbackContact(std::uint16_t(key >> 16), std::uint16_t(key & 0xffff)));
    if (contact->setOccupant(locId))
        changes.contacts.add(key);
    return changes;
}

RailwayChanges RailwayState::reportDevicePosition(std::int64_t id, std::optional<int> position) {
    RailwayChanges changes;
    Accessory* accessory = accessories_.find(id);
    if (!accessory)
        return changes;
    if (position ? accessory->confirmPosition(*position) : accessory->isPositionReported()) {
        if (!position)
            accessory->forgetReported();
        changes.accessories.add(id);
    }
    return changes;
}

RailwayChanges RailwayState::reportDeviceContact(ContactKey key, std::optional<bool> occupied,
                                                 const QDateTime& now) {
    RailwayChanges changes;
    FeedbackContact* contact = contacts_.find(key);
    if (!contact)
        contact = &contacts_.put(key, FeedbackContact(std::uint16_t(key >> 16), std::uint16_t(key & 0xffff)));
    if (occupied ? contact->confirm(*occupied, now) : contact->known()) {
        if (!occupied)
            contact->forgetReported();
        changes.contacts.add(key);
    }
    return changes;
}

void RailwayState::applyDevices(const station::StationUpdates& updates, const QDateTime& now,
                                RailwayChanges& changes) {
    for (const cs2::DeviceIdentity& identity : updates.devices)
        if (!devices_.find(identity.uid)) {
            devices_.put(identity.uid, Device(identity));
            changes.devices.add(identity.uid);
        }
    for (const station::ReadingValue& reading : updates.readings) {
        Device* device = devices_.find(reading.device);
        StatusChannel* channel = device ? device->channel(reading.channel) : nullptr;
        if (channel && channel->confirm(reading.raw, now))
            changes.devices.add(reading.device);
        DeviceSetting* setting = device && !channel ? device->setting(reading.channel) : nullptr;
        if (setting && setting->confirm(reading.raw))
            changes.devices.add(reading.device);
    }
}

} // namespace stellwerk::model
