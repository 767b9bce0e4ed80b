#pragma once

#include "model/FeedbackContact.h"

#include <QPointer>
#include <cstdint>
#include <map>

namespace stellwerk::model {

class Railway;

// Which locomotive is on which contact, as a source outside the station reports it (the embedded simulated
// station moving the demo's trains): kept across sessions and handed to each railway made after a start-up,
// since a real station cannot say where a locomotive is and a new railway would otherwise not know.
class OccupantBook final {
public:
    // The railway now shown (null: none); it learns every occupant known so far.
    void setRailway(Railway* railway);
    // A locomotive came onto a contact, or the contact's locomotive left it (locId 0: nobody known).
    void report(ContactKey key, std::uint32_t locId);
    // Forgets every occupant (a new simulation places its trains anew).
    void clear();
    std::uint32_t occupantOf(ContactKey key) const;

private:
    std::map<ContactKey, std::uint32_t> m_occupants;
    QPointer<Railway> m_railway;
};

} // namespace stellwerk::model
