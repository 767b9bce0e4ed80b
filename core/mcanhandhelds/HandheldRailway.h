#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::mcanhandhelds {

// What a locomotive looks like on a handheld's display (M-CAN document 6.7.1 and 6.7.2).
enum class LocoKind : std::uint8_t { None = 0, Electric = 1, Diesel = 2, Steam = 3 };
enum class RailFormat : std::uint8_t { Unknown = 0, Mfx = 1, Dcc = 2, Motorola = 3 };

// The kind lokomotive.cs2 keeps for the MS1 (`.symbol`: 0 electric, 1 diesel, 2 steam, 3 none).
constexpr LocoKind kindOfSymbol(int symbol) {
    switch (symbol) {
    case 0:
        return LocoKind::Electric;
    case 1:
        return LocoKind::Diesel;
    case 2:
        return LocoKind::Steam;
    default:
        return LocoKind::None;
    }
}

// One function key of a locomotive as the handheld shows it.
struct HandheldFunction {
    int index = 0; // f0 = 0
    bool momentary = false;
};

// A locomotive the handhelds may drive: the railway's Loc-ID and what the handheld shows of it.
struct HandheldLoco {
    std::uint32_t locId = 0;
    std::string name;
    LocoKind kind = LocoKind::None;
    RailFormat format = RailFormat::Unknown;
    std::vector<HandheldFunction> functions; // in key order; an MS1 shows the first eight
};

// How a locomotive runs now, in the railway's terms.
struct LocoDrive {
    int speed = 0; // 0..1000
    bool forward = true;
    std::uint32_t functions = 0; // bit n: function n is on
};

// The railway as the handhelds' master needs it, in railway words and free of any protocol: the
// locomotives, how they run, the track power, and the intents a handheld can have. The app implements it on
// its railway model (the intents become CS2 commands on the station), the simulated CS2 on its own state.
// Whoever implements it tells the master of changes (HandheldMaster::locoChanged, powerChanged).
class HandheldRailway {
public:
    virtual ~HandheldRailway() = default;

    virtual std::vector<HandheldLoco> locomotives() const = 0;
    // nullopt for a Loc-ID the railway does not know.
    virtual std::optional<LocoDrive> drive(std::uint32_t locId) const = 0;
    // nullopt while the track power is not known.
    virtual std::optional<bool> powerOn() const = 0;

    virtual void setSpeed(std::uint32_t locId, int speed) = 0;
    virtual void setDirection(std::uint32_t locId, bool forward) = 0;
    virtual void setFunction(std::uint32_t locId, int function, bool on) = 0;
    virtual void setPower(bool on) = 0;
};

} // namespace stellwerk::mcanhandhelds
