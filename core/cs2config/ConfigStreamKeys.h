#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace stellwerk::cs2config {

// How a station sends the file of a key in its 0x21 stream.
enum class StreamFormat : std::uint8_t {
    Compressed, // u32 BE size + zlib stream (the .cs2/.sr2 files of a CS2)
    Ms2Text,    // plain text, every line padded with spaces to an 8-byte frame boundary
    Binary,     // plain bytes (MS2 loco database, language file)
};

// What a requester sends after the key frame (document 7.1, column "Folge-Info").
enum class FollowUp : std::uint8_t {
    None,
    LocoName, // two frames with the first 16 bytes of the loco name, zero padded
    Range,    // one frame with ASCII "<first> <count>"
};

// One row of the document's table of file keys (7.1), plus the keys the field notes add.
struct ConfigFileKey {
    std::string_view key;      // as on the wire; "gbs-#" stands for gbs-0, gbs-1, ...
    std::string_view fileName; // the file it carries; for gbs-# the name is gbs-<n>.cs2
    std::string_view sender;   // who asks for it in the document: "MS2" or "CS2"
    FollowUp followUp;
    StreamFormat format;
    std::string_view meaning;

    std::uint8_t followUpFrames() const;
};

// Every known key, in the document's order.
std::span<const ConfigFileKey> configFileKeys();

// The table row of a key as sent on the wire ("gbs-3" finds "gbs-#"); nullopt for unknown keys.
std::optional<ConfigFileKey> findConfigFileKey(std::string_view key);

// The name to store a key's file under ("loks" -> "lokomotive.cs2", "gbs-3" -> "gbs-3.cs2");
// empty for unknown keys, so that nothing read from the bus becomes a path.
std::string fileNameForKey(std::string_view key);

} // namespace stellwerk::cs2config
