#pragma once

#include "base/Expected.h"
#include "cs2/Header.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// The "<first> <count>" qualifier of loknamen and maginfo.
struct RequestRange {
    unsigned first = 0;
    unsigned count = 0;
    friend bool operator==(const RequestRange&, const RequestRange&) = default;
};

// A request for a configuration file (command 0x20, document 7.1): the key and, for lokinfo,
// loknamen and maginfo, the text of the follow-up frames. Valid by construction.
class ConfigRequest {
public:
    static constexpr std::size_t MaxKeyLength = 8;
    static constexpr std::size_t MaxLocoNameLength = 16;

    // Any key of 1..8 bytes; `qualifier` is the follow-up text, which only keys with follow-up
    // frames carry (at most 8 bytes per frame).
    static Expected<ConfigRequest, std::string> forKey(std::string_view key, std::string_view qualifier = {});
    // lokinfo: the loco name is cut to its first 16 bytes, never inside a UTF-8 character.
    static ConfigRequest locoInfo(std::string_view locoName);
    static Expected<ConfigRequest, std::string> locoNames(unsigned first, unsigned count);
    static Expected<ConfigRequest, std::string> accessoryInfo(unsigned first, unsigned count);

    const std::string& key() const { return key_; }
    const std::string& qualifier() const { return qualifier_; }
    std::uint8_t followUpFrames() const;
    // The range of a loknamen/maginfo request; nullopt when the qualifier is not "<first> <count>".
    std::optional<RequestRange> range() const;

    // The key frame and the follow-up frames, DLC 8, zero padded. With `response` set they are the
    // station's acknowledgement (same bytes and hash, response bit set).
    std::vector<can::CanFrame> frames(std::uint16_t hash, bool response = false) const;

    friend bool operator==(const ConfigRequest&, const ConfigRequest&) = default;

private:
    ConfigRequest(std::string key, std::string qualifier)
        : key_(std::move(key)), qualifier_(std::move(qualifier)) {}

    std::string key_;
    std::string qualifier_;
};

} // namespace stellwerk::cs2config
