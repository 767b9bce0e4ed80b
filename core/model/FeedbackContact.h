#pragma once

#include <QDateTime>
#include <QString>
#include <cstdint>

namespace stellwerk::model {

// A contact's identity on the bus: feedback device id (high 16 bits) and contact number (document 5).
using ContactKey = std::uint32_t;

constexpr ContactKey contactKey(std::uint16_t device, std::uint16_t contact) {
    return ContactKey(device) << 16 | contact;
}

// An S88 feedback contact: whether a train occupies it and since when, as the bus last reported.
class FeedbackContact {
public:
    FeedbackContact() = default;
    FeedbackContact(std::uint16_t device, std::uint16_t contact, QString name = {});

    ContactKey key() const { return contactKey(device_, contact_); }
    std::uint16_t device() const { return device_; }
    std::uint16_t contact() const { return contact_; }
    const QString& name() const { return name_; }
    void setName(const QString& name) { name_ = name; }

    bool occupied() const { return occupied_; }
    // False until the bus reported the contact (answer to the start-up query or an event), and again
    // from the moment the station can no longer be heard until it reports the contact again: a view
    // shows the last state as "not reported".
    bool known() const { return known_; }
    void forgetReported() { known_ = false; }
    // When the state last changed (local clock); invalid before the first change.
    const QDateTime& lastChange() const { return lastChange_; }

    // Returns true when the state or its knownness changed. A contact reported free has no occupant.
    bool confirm(bool occupied, const QDateTime& now);

    // The Loc-ID of the locomotive on the contact, as the simulator or the user says (the station cannot
    // report it); 0 when nobody said. Returns true when it changed.
    std::uint32_t occupant() const { return occupant_; }
    bool setOccupant(std::uint32_t locId);

private:
    std::uint16_t device_ = 0;
    std::uint16_t contact_ = 0;
    QString name_;
    bool occupied_ = false;
    bool known_ = false;
    std::uint32_t occupant_ = 0;
    QDateTime lastChange_;
};

} // namespace stellwerk::model
