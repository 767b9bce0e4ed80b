#pragma once

#include "base/Expected.h"
#include "can/CanFrame.h"

#include <string>
#include <string_view>

namespace stellwerk::can {

// The ways people write a frame down.
enum class FrameNotation {
    Document,  // "00004711 5 00 00 00 00 00" as in Märklin's protocol document
    Candump,   // "00004711#0000000000", optionally "(1700000000.000000) can0 " before it
    Bracketed, // "can0  00004711   [5]  00 00 00 00 00" (candump screen, can2udp/can-monitor logs)
    Network,   // the 13-byte UDP/TCP form as 26 hex digits
};

struct ParsedFrame {
    CanFrame frame;
    FrameNotation notation;
};

// Reads one frame from a line in any of the notations. An identifier of up to 3 hex digits is a standard
// (11-bit) one, a longer one extended (29-bit); the network form carries extended frames only. Text after the
// data bytes is taken as a comment (the document's examples carry one). The error says what is wrong with the
// line.
Expected<ParsedFrame, std::string> parseFrame(std::string_view line);

// Standard identifiers are written with 3 hex digits ("123 2 01 02", "123#0102"), extended with 8.
std::string formatDocument(const CanFrame& frame); // "00004711 5 00 00 00 00 00"
std::string formatCandump(const CanFrame& frame);  // "00004711#0000000000"
// Extended frames only (check CanFrame::fitsNetworkForm()).
std::string formatNetwork(const CanFrame& frame); // "00004711050000000000000000"

// The identifier as both notations write it: 3 hex digits for a standard frame, 8 for an extended one.
std::string formatId(const CanFrame& frame);
// Appends `value` in upper-case hex with at least `digits` digits (the one hex writer of the reports).
void appendHex(std::string& out, std::uint64_t value, unsigned digits);

} // namespace stellwerk::can
