#pragma once

#include "can/CanFrame.h"
#include "ro/Codec.h"

#include <cstdint>
#include <optional>
#include <string>

namespace stellwerk::ro {

// The CAN identifiers of one RO module. The document gives none (notes R1): requests go to `request`,
// answers come back on `answer`, in 29-bit (extended) or 11-bit (standard) frames. Answers carry no
// module address, so the answer id is the only thing that tells modules apart.
struct FrameIds {
    std::uint32_t request = 0;
    std::uint32_t answer = 0;
    bool extended = true;
    friend bool operator==(const FrameIds&, const FrameIds&) = default;
};

// Which way an RO frame goes, told by its identifier alone.
enum class Direction : std::uint8_t { Request, Answer };

// Whether the frame travels on these ids, and which way; nullopt for any other frame.
std::optional<Direction> directionOf(const can::CanFrame& frame, const FrameIds& ids);

// A run of registers that hold relays or inputs: `count` of them from bit 0 of the little-endian value at
// `address`, read or written `width` wide (004 §3.4: relay n is bit n-1 of the word at 0x0000).
struct RegisterBlock {
    std::uint16_t address = 0;
    Width width = Width::Word;
    std::uint8_t count = 0; // 0: the module has none
    friend bool operator==(const RegisterBlock&, const RegisterBlock&) = default;
};

// What Stellwerk must know of one RO module that the document leaves to the missing "RO-Registerbelegung"
// (004 §2.3) and to the module's switches: its ids and frame format, where its outputs, inputs and input
// change flags are, and how long a read request is. Configurable per module since a real one may differ.
struct RoProfile {
    std::string name;
    FrameIds ids;
    RegisterBlock outputs;
    RegisterBlock inputs;
    std::optional<RegisterBlock> changeFlags; // read-to-clear (004 §2.1)
    ReadRequestSize readRequestSize = ReadRequestSize::Eight;

    // The profile of Stellwerk's simulated module n (Stellwerk-defined, not from the document): request id
    // 0x01FE0000|n, answer id 0x01FF0000|n (29-bit, in the band CS2 nodes ignore, notes B7), 16 relays at
    // 0x0000 (word), 16 inputs at 0x0020 (word), change flags at 0x0022 (word).
    static RoProfile simulator(std::uint16_t module);

    // Why the profile cannot be used (an id too wide for its format, request and answer ids equal, a
    // block with more registers than its width has bits or past the end of memory); empty when usable.
    std::string problem() const;

    can::CanFrame requestFrame(const Request& request) const;
    can::CanFrame answerFrame(const Answer& answer) const;
};

// The frame with these ids carrying the payload (standard or extended as the ids say).
can::CanFrame frameOf(std::uint32_t id, bool extended, const Payload& payload);

} // namespace stellwerk::ro
