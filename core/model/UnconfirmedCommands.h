#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

namespace stellwerk::model {

// What one command changes on the layout, as far as bringing it back is concerned.
struct CommandTarget {
    enum class Kind : std::uint8_t { Speed, Direction, Function, Accessory, Address, Power };

    Kind kind = Kind::Power;
    std::int64_t id = 0; // the locomotive's Loc-ID, the accessory's keyboard id or the address; 0 for power
    int functionNumber = -1; // for Kind::Function

    static CommandTarget speed(std::uint32_t loco) { return {Kind::Speed, loco, -1}; }
    static CommandTarget direction(std::uint32_t loco) { return {Kind::Direction, loco, -1}; }
    static CommandTarget function(std::uint32_t loco, int number) { return {Kind::Function, loco, number}; }
    static CommandTarget accessory(std::int64_t id) { return {Kind::Accessory, id, -1}; }
    static CommandTarget address(std::int64_t address) { return {Kind::Address, address, -1}; }
    static CommandTarget power() { return {Kind::Power, 0, -1}; }

    bool isLocomotive() const {
        return kind == Kind::Speed || kind == Kind::Direction || kind == Kind::Function;
    }
    bool operator==(const CommandTarget& other) const { return key() == other.key(); }
    bool operator<(const CommandTarget& other) const { return key() < other.key(); }
    std::tuple<Kind, std::int64_t, int> key() const { return {kind, id, functionNumber}; }
};

// What Stellwerk does after trouble with the locomotives that had a command the station did not confirm.
enum class Aftermath : std::uint8_t {
    RestoreConfirmed, // each gets back what the station last confirmed (a speed never goes up)
    StopLocomotives,  // each is stopped (speed 0)
};

// One step of bringing the layout back: what to send to a target, and why.
struct Correction {
    CommandTarget target;
    int failedValue = 0;          // what the command the station did not confirm asked for
    std::optional<int> sentValue; // what is sent to bring it back; nullopt: left as the station has it
    bool carriedOutLate = false;  // the station was seen carrying the unconfirmed command out
};

// What to do when the station is heard again: corrections to send at once, and the locomotive states to
// ask for first (the answer shows whether a failed command was carried out, or someone else changed it).
struct Recovery {
    std::vector<Correction> corrections;
    std::vector<CommandTarget> queries;
};

// The book of commands the station did not confirm (given up, or cut off with the connection) and that it
// may still carry out: frames already on the wire cannot be withdrawn, and a station that stalled reads
// them when it wakes. For each target it keeps the value to bring back (what the person last saw
// confirmed) and the values that must not stay. When the station is heard again, a locomotive's state is
// asked for (the station can report it) and an accessory or the power, which it cannot report, is sent
// back at once; a value of a failed command that the station reports then, or later while the target is
// watched, is undone. Corrections never make a train faster, never start one and never switch the track
// power on: a late stop is left in place. Values: speed 0..1000, direction 0 forward / 1 backward,
// function 0 off / 1 on, accessory and address positions, power 0 off / 1 on.
class UnconfirmedCommands {
public:
    using Clock = std::chrono::steady_clock;

    // How long a target stays watched after it was brought back: a late copy of the failed command that
    // arrives meanwhile (through a connection the station reads later) is corrected again.
    static constexpr std::chrono::milliseconds WatchTime{5000};

    void setAftermath(Aftermath aftermath) { aftermath_ = aftermath; }
    Aftermath aftermath() const { return aftermath_; }

    // A command to `target` asking for `value` was not confirmed. `confirmed` is what the station last
    // reported for it (nullopt: nothing; a speed then comes back as 0, the power as off).
    void failed(CommandTarget target, int value, std::optional<int> confirmed);
    // The station acknowledged our command to `target`: that value is now the confirmed one.
    void acknowledged(CommandTarget target, int value, Clock::time_point now);
    // The station reports `value` for `target`. A value of a failed command means the station carried it
    // out late: the correction says what to send (or that it stays). Any other value is a change someone
    // made (another controller, the station itself) and becomes the value to bring back.
    std::optional<Correction> reported(CommandTarget target, int value, Clock::time_point now);
    // The station was heard after commands failed: what to do for every target not brought back yet.
    Recovery heardAgain(Clock::time_point now);
    // A question heardAgain() asked got no answer: it is asked again when the station is next heard.
    void queryUnanswered(CommandTarget target);

    // The value a target is brought back to, where the book watches it and knows one.
    std::optional<int> restoreValue(CommandTarget target) const;
    std::vector<CommandTarget> targets() const;
    bool empty() const { return entries_.empty(); }
    bool watches(CommandTarget target) const { return entries_.count(target) != 0; }
    std::size_t size() const { return entries_.size(); }
    // Forgets targets whose watch ran out.
    void settle(Clock::time_point now);

private:
    enum class Phase : std::uint8_t { Waiting, Querying, Correcting, Watching };

    struct Entry {
        std::optional<int> restore;
        std::vector<int> failedValues;
        Phase phase = Phase::Waiting;
        Clock::time_point until;
    };

    static std::optional<int> restoreFor(CommandTarget target, std::optional<int> confirmed);
    std::optional<int> correctionFor(CommandTarget target, const Entry& entry) const;
    static bool mustUndo(CommandTarget target, int failedValue, int restore);
    std::optional<int> stopValueFor(CommandTarget target) const;

    Aftermath aftermath_ = Aftermath::RestoreConfirmed;
    std::map<CommandTarget, Entry> entries_;
};

} // namespace stellwerk::model
