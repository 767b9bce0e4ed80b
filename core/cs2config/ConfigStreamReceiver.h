#pragma once

#include "base/Expected.h"
#include "cs2/Header.h"
#include "cs2/Messages.h"
#include "cs2config/ConfigStreamError.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// A configuration file that arrived complete and intact in a config-data stream.
struct ReceivedConfigFile {
    std::string key; // the requested key ("loks", "gbs-2"); empty when no request was expected
    std::uint16_t hash = 0;
    bool broadcast = false;                // DLC 7 header: "configuration changed"
    std::uint8_t broadcastValue = 0;       // its seventh byte
    std::uint32_t length = 0;              // as the header announces
    std::uint16_t crc = 0;                 // as the header announces and the data confirmed
    bool compressed = false;               // size prefix + zlib stream (inflated into contents)
    std::vector<std::uint8_t> streamBytes; // every data byte received, frame padding included
    std::string contents;                  // the file: inflated, or the text without padding
};

// How much of the current (or last) stream has arrived, for a progress bar; `active` while it is
// being collected.
struct StreamProgress {
    std::uint16_t hash = 0;
    std::size_t received = 0;  // data bytes, at most `announced`
    std::size_t announced = 0; // the header's length
    bool active = false;
};

// Bounds that keep a broken or hostile sender from exhausting memory.
struct StreamLimits {
    // Largest stream and largest file (inflated) accepted; larger ones are refused before any
    // memory is spent on them.
    std::size_t maxFileSize = std::size_t(16) << 20;
};

using StreamOutcome = Expected<ReceivedConfigFile, ConfigStreamError>;

// Reassembles one config-data stream at a time (command 0x21, document 7.2) from decoded frames:
// header (DLC 6, or 7 for a broadcast), then DLC-8 data frames up to the announced length. Checks
// the CRC over every received byte, inflates compressed files (the requested key's format says which;
// without a key, a payload that inflates, or is not text) and strips the MS2 line padding.
// Each call returns the streams it finished: good files or errors (usually none, at most two when a
// header cuts short the stream before it).
class ConfigStreamReceiver {
public:
    using ProgressHandler = std::function<void(const StreamProgress&)>;

    explicit ConfigStreamReceiver(StreamLimits limits = {});

    // The next stream with this hash answers a request for `key` (the result carries the key).
    void expectFile(std::string key, std::uint16_t hash);
    // Called after the header and after every data frame of a stream.
    void onProgress(ProgressHandler handler) { onProgress_ = std::move(handler); }

    std::vector<StreamOutcome> feed(const cs2::ConfigDataStream& frame, std::uint16_t hash);
    // A raw frame: 0x21 frames are decoded and fed; one with another length (not 6, 7 or 8) aborts
    // the stream it belongs to. Other commands are ignored.
    std::vector<StreamOutcome> feed(const can::CanFrame& frame);
    // The input ended: an unfinished stream is reported as incomplete.
    std::optional<StreamOutcome> finish();

    bool collecting() const { return state_ == State::Collecting; }
    StreamProgress progress() const;

private:
    enum class State : std::uint8_t { Idle, Collecting, Finished, Discarding };

    std::vector<StreamOutcome> start(const cs2::ConfigDataStream& header, std::uint16_t hash);
    std::vector<StreamOutcome> append(const cs2::ConfigDataStream& data);
    std::vector<StreamOutcome> stray(std::uint16_t hash);
    StreamOutcome complete();
    StreamOutcome decodeFile(ReceivedConfigFile file) const;
    ConfigStreamError fail(StreamErrorKind kind, const std::string& what);
    std::string describe() const;
    void reportProgress() const;

    StreamLimits limits_;
    State state_ = State::Idle;
    std::uint16_t hash_ = 0;
    cs2::ConfigDataStream header_;
    std::string key_;
    std::optional<std::pair<std::string, std::uint16_t>> expected_;
    std::vector<std::uint8_t> bytes_;
    ProgressHandler onProgress_;
};

} // namespace stellwerk::cs2config
