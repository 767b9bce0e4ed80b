#pragma once

#include "base/Expected.h"
#include "cs2config/ConfigStreamError.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// The bytes inside a config-data stream, without the frames: the compressed form of the CS2
// (u32 BE size + zlib stream) and the MS2's text form (lines padded to 8-byte frame boundaries).
namespace stellwerk::cs2config::payload {

// True when the bytes start with a 4-byte size followed by a zlib header (0x78, valid check bits).
bool isCompressed(std::span<const std::uint8_t> bytes);

// The size a compressed payload announces in its first four bytes (0 when shorter).
std::uint32_t announcedSize(std::span<const std::uint8_t> bytes);

// u32 BE size + zlib stream (compress2, default level: "78 9C"), as a CS2 sends its files.
std::vector<std::uint8_t> compress(std::string_view contents);

// Inflates a compressed payload in chunks. Never allocates more than the smaller of the announced
// size and `limit` (plus one chunk): a lying prefix or a zip bomb ends in an error, not in memory
// exhaustion. Trailing bytes after the end of the zlib stream (frame padding) are ignored.
Expected<std::string, ConfigStreamError> inflate(std::span<const std::uint8_t> bytes, std::size_t limit);

// MS2 text form: after each newline, spaces up to the next multiple of 8 bytes, so that every line
// starts a frame.
std::string padLines(std::string_view text);

// True when `text` is in that form: every newline is followed by spaces up to an 8-byte boundary
// (or the end of the text).
bool hasPaddedLines(std::string_view text);

// Removes the padding that padLines() adds; padLines() then stripLinePadding() gives the input back.
std::string stripLinePadding(std::string_view text);

// True when the bytes read as text: no control bytes but tab and line ends, apart from trailing zero
// bytes (frame padding). zlib output never does; a plain .cs2 or MS2 text file does.
bool isText(std::span<const std::uint8_t> bytes);
// The file of a plain (uncompressed) stream, given the announced length of bytes. Text loses its
// line padding when in the MS2 form, and trailing zero bytes when the length is a multiple of 8
// (frame padding, which a CS3 counts in the length). Bytes with a zero byte before the trailing
// ones are binary (lokdb) and are kept as they are.
std::string plainText(std::span<const std::uint8_t> bytes);

} // namespace stellwerk::cs2config::payload
