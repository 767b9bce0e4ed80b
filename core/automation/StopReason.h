#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace stellwerk::automation {

// Why the automation stopped a train (a fault, an overrun, a lost train), in parts: the window puts them in
// the user's language, the command line prints describe()'s English sentence.
struct StopReason {
    enum class Why : std::uint8_t {
        None,
        NoLongerSeen,         // after the station was silent, not seen where it stood
        OtherEnteredItsWay,   // `other` entered `block`, on this train's way
        RanIntoUnreserved,    // ran on into `block`, not reserved for it: track power off
        UnknownOccupantAhead, // an unknown occupant in `block` on its way
        DidNotArrive,         // not seen arriving in `block` in time
        TurnoutNotConfirmed,  // `turnout` not confirmed in `position` after `attempts`
        TurnoutSwitchedUnder, // `turnout` switched to `position` by someone else, on its way
    };
    Why why = Why::None;
    std::string train; // the train stopped, by name
    std::string other; // OtherEnteredItsWay: the train that entered
    std::string block; // the block's name
    std::int64_t turnout = 0;
    int position = 0;
    int attempts = 0;

    bool operator==(const StopReason&) const = default;

    static StopReason noLongerSeen(std::string train) { return with(Why::NoLongerSeen, std::move(train)); }
    static StopReason otherEnteredItsWay(std::string train, std::string other, std::string block) {
        StopReason r = with(Why::OtherEnteredItsWay, std::move(train), std::move(block));
        r.other = std::move(other);
        return r;
    }
    static StopReason ranIntoUnreserved(std::string train, std::string block) {
        return with(Why::RanIntoUnreserved, std::move(train), std::move(block));
    }
    static StopReason unknownOccupantAhead(std::string train, std::string block) {
        return with(Why::UnknownOccupantAhead, std::move(train), std::move(block));
    }
    static StopReason didNotArrive(std::string train, std::string block) {
        return with(Why::DidNotArrive, std::move(train), std::move(block));
    }
    static StopReason turnoutNotConfirmed(std::string train, std::int64_t turnout, int position,
                                          int attempts) {
        StopReason r = turnoutSwitchedUnder(std::move(train), turnout, position);
        r.why = Why::TurnoutNotConfirmed;
        r.attempts = attempts;
        return r;
    }
    static StopReason turnoutSwitchedUnder(std::string train, std::int64_t turnout, int position) {
        StopReason r = with(Why::TurnoutSwitchedUnder, std::move(train));
        r.turnout = turnout;
        r.position = position;
        return r;
    }

private:
    static StopReason with(Why why, std::string train, std::string block = {}) {
        StopReason r;
        r.why = why;
        r.train = std::move(train);
        r.block = std::move(block);
        return r;
    }
};

// The reason as one English sentence a person can act on ("turnout 2 was not confirmed …").
std::string describe(const StopReason& reason);

} // namespace stellwerk::automation
