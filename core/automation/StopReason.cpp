#include "automation/StopReason.h"

namespace stellwerk::automation {

namespace {

std::string quoted(const std::string& name) {
    return "\"" + name + "\"";
}

} // namespace

std::string describe(const StopReason& r) {
    using Why = StopReason::Why;
    switch (r.why) {
    case Why::None:
        return {};
    case Why::NoLongerSeen:
        return r.train + " is no longer seen where it stood: place it again";
    case Why::OtherEnteredItsWay:
        return r.other + " entered " + quoted(r.block) + " on the way of " + r.train;
    case Why::RanIntoUnreserved:
        return r.train + " ran on into " + quoted(r.block) +
               ", which was not reserved for it: track power off";
    case Why::UnknownOccupantAhead:
        return r.train + " stopped: an unknown occupant in " + quoted(r.block) + " on its way";
    case Why::DidNotArrive:
        return r.train + " did not arrive in " + quoted(r.block) + " in time: stopped, place it again";
    case Why::TurnoutNotConfirmed:
        return "turnout " + std::to_string(r.turnout) + " was not confirmed in position " +
               std::to_string(r.position) + " after " + std::to_string(r.attempts) + " attempts: " + r.train +
               " does not depart, its way is given back";
    case Why::TurnoutSwitchedUnder:
        return "turnout " + std::to_string(r.turnout) + " was switched to position " +
               std::to_string(r.position) + " on the way reserved for " + r.train + ": stopped";
    }
    return {};
}

} // namespace stellwerk::automation
