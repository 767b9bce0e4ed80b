#pragma once

#include "mcanhandhelds/HandheldRailway.h"

#include <array>
#include <cstdint>
#include <string>

namespace stellwerk::mcanhandhelds {

// An MS1 drives with 127 steps and a direction bit (document 5.4, 6.7.3); the railway with 0..1000.
int railwaySpeed(int handheldSpeed);
int handheldSpeed(int railwaySpeed);
// Function 1 (speed and direction) as one byte: speed 0..127, bit 7 = reverse.
std::uint8_t speedByte(int handheldSpeed, bool forward);

// The name an MS1 can show: 16 characters of ASCII, umlauts spelt out ("Köf" -> "Koef"), anything else '?'.
std::string handheldName(const std::string& utf8);
// A name as 4 segments of 4 characters, NUL-padded (document 6.4.2, 6.7.4).
std::array<char, 16> nameSegments(const std::string& name);

} // namespace stellwerk::mcanhandhelds
