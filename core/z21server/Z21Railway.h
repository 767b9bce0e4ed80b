#pragma once

#include "z21/Replies.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::model {
class Railway;
class Z21Addresses;
} // namespace stellwerk::model

namespace stellwerk::z21server {

// The railway in Z21 terms: locomotives on their Z21 addresses (the address book), turnouts on Z21 numbers
// (keyboard number = Z21 number + 1), the loco and turnout info and the system state a client is sent, all
// read from the railway as the station reported it. The one place where the server's numbers meet the model.
class Z21Railway {
public:
    Z21Railway(model::Railway& railway, model::Z21Addresses& addresses);

    model::Railway& railway() const { return railway_; }
    // Gives every MM and mfx locomotive of the railway a Z21 address it lacks.
    void coverLocomotives();
    std::optional<std::uint32_t> locoAt(std::uint16_t address) const;
    std::optional<std::uint16_t> addressOf(std::uint32_t locId) const;

    // Speed, direction and functions as the railway shows them, in the client's steps; an address without a
    // locomotive reads as standing.
    z21::LocoInfo locoInfo(std::uint16_t address, z21::SpeedStepMode mode, bool busy) const;
    z21::DecoderFormat locoFormat(std::uint16_t address) const;
    // Output 1 for position 0 (round, red), output 2 for position 1 (straight, green); not switched while the
    // station has not reported it.
    z21::TurnoutInfo turnoutInfo(std::uint16_t z21Number) const;
    z21::DecoderFormat turnoutFormat(std::uint16_t z21Number) const;
    void switchTurnout(std::uint16_t z21Number, bool secondOutput);
    // Central state bits: track voltage off while the power is off or not known, emergency stop while halted.
    std::uint8_t centralState() const;
    // The station's readings (main and programming current, voltage, temperature) and its central state.
    z21::SystemState systemState() const;

private:
    std::vector<std::uint32_t> locIds() const;

    model::Railway& railway_;
    model::Z21Addresses& addresses_;
};

} // namespace stellwerk::z21server
