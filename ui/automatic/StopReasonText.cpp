#include "automatic/StopReasonText.h"

namespace stellwerk::ui {

QString StopReasonText::of(const automation::StopReason& r) {
    using Why = automation::StopReason::Why;
    const QString train = QString::fromStdString(r.train);
    const QString block = QString::fromStdString(r.block);
    switch (r.why) {
    case Why::None:
        return {};
    case Why::NoLongerSeen:
        return tr("%1 is no longer seen where it stood: place it again").arg(train);
    case Why::OtherEnteredItsWay:
        return tr("%1 entered \"%2\" on the way of %3").arg(QString::fromStdString(r.other), block, train);
    case Why::RanIntoUnreserved:
        return tr("%1 ran on into \"%2\", which was not reserved for it: track power off").arg(train, block);
    case Why::UnknownOccupantAhead:
        return tr("%1 stopped: an unknown occupant in \"%2\" on its way").arg(train, block);
    case Why::DidNotArrive:
        return tr("%1 did not arrive in \"%2\" in time: stopped, place it again").arg(train, block);
    case Why::TurnoutNotConfirmed:
        return tr("turnout %1 was not confirmed in position %2 after %3 attempts: %4 does not depart, its "
                  "way "
                  "is given back")
            .arg(r.turnout)
            .arg(r.position)
            .arg(r.attempts)
            .arg(train);
    case Why::TurnoutSwitchedUnder:
        return tr("turnout %1 was switched to position %2 on the way reserved for %3: stopped")
            .arg(r.turnout)
            .arg(r.position)
            .arg(train);
    }
    return {};
}

} // namespace stellwerk::ui
