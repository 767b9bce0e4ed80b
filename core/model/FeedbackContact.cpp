#include "model/FeedbackContact.h"

namespace stellwerk::model {

FeedbackContact::FeedbackContact(std::uint16_t device, std::uint16_t contact, QString name)
    : device_(device), contact_(contact), name_(std::move(name)) {}

bool FeedbackContact::confirm(bool occupied, const QDateTime& now) {
    if (known_ && occupied == occupied_)
        return false;
    if (occupied != occupied_ || !lastChange_.isValid())
        lastChange_ = now; // reported again unchanged: it has been so since the last change
    occupied_ = occupied;
    known_ = true;
    if (!occupied)
        occupant_ = 0; // the train left
    return true;
}

bool FeedbackContact::setOccupant(std::uint32_t locId) {
    if (locId == occupant_)
        return false;
    occupant_ = locId;
    return true;
}

} // namespace stellwerk::model
