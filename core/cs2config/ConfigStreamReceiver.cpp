#include "cs2config/ConfigStreamReceiver.h"

#include "cs2/Codec.h"
#include "cs2/Crc16.h"
#include "cs2config/ConfigStreamKeys.h"
#include "cs2config/ConfigStreamPayload.h"

#include <algorithm>
#include <cstdio>

namespace stellwerk::cs2config {
namespace {

using Form = cs2::ConfigDataStream::Form;

// Reserved up front at most; the rest grows as frames arrive, whatever the header claims.
constexpr std::size_t InitialReserve = 64 * 1024;

std::string hex16(std::uint16_t value) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "0x%04X", value);
    return buffer;
}

std::string ofAnnounced(std::size_t received, std::size_t announced) {
    return std::to_string(received) + " of " + std::to_string(announced) + " bytes";
}

} // namespace

ConfigStreamReceiver::ConfigStreamReceiver(StreamLimits limits) : limits_(limits) {}

void ConfigStreamReceiver::expectFile(std::string key, std::uint16_t hash) {
    expected_.emplace(std::move(key), hash);
}

std::vector<StreamOutcome> ConfigStreamReceiver::feed(const cs2::ConfigDataStream& frame,
                                                      std::uint16_t hash) {
    if (frame.form != Form::Data)
        return start(frame, hash);
    if (state_ == State::Collecting && hash == hash_)
        return append(frame);
    if (state_ == State::Collecting)
        return {}; // another requester's stream: not ours to judge
    return stray(hash);
}

std::vector<StreamOutcome> ConfigStreamReceiver::feed(const can::CanFrame& frame) {
    if (cs2::command(frame) != std::uint8_t(cs2::Command::ConfigDataStream))
        return {};
    const auto decoded = cs2::decode(frame);
    if (decoded)
        return feed(std::get<cs2::ConfigDataStream>(decoded->body), cs2::hash(frame));
    if (state_ != State::Collecting || cs2::hash(frame) != hash_)
        return {};
    return {fail(StreamErrorKind::Interrupted, "a frame with DLC " + std::to_string(frame.dlc) +
                                                   " arrived after " +
                                                   ofAnnounced(bytes_.size(), header_.length) +
                                                   "; reception aborted, the bytes are dropped")};
}

std::optional<StreamOutcome> ConfigStreamReceiver::finish() {
    if (state_ != State::Collecting) {
        state_ = State::Idle;
        return std::nullopt;
    }
    StreamOutcome outcome = fail(StreamErrorKind::Incomplete,
                                 "the input ended after " + ofAnnounced(bytes_.size(), header_.length));
    state_ = State::Idle;
    return outcome;
}

StreamProgress ConfigStreamReceiver::progress() const {
    return {hash_, std::min<std::size_t>(bytes_.size(), header_.length), header_.length,
            state_ == State::Collecting};
}

std::vector<StreamOutcome> ConfigStreamReceiver::start(const cs2::ConfigDataStream& header,
                                                       std::uint16_t hash) {
    std::vector<StreamOutcome> outcomes;
    if (state_ == State::Collecting)
        outcomes.emplace_back(
            fail(StreamErrorKind::Interrupted, "a new header arrived after " +
                                                   ofAnnounced(bytes_.size(), header_.length) +
                                                   "; the bytes are dropped"));
    state_ = State::Collecting;
    hash_ = hash;
    header_ = header;
    key_.clear();
    if (expected_ && expected_->second == hash)
        key_ = std::move(expected_->first), expected_.reset();
    bytes_.clear();
    if (header.length > limits_.maxFileSize) {
        outcomes.emplace_back(fail(StreamErrorKind::TooLarge,
                                   "the header announces " + std::to_string(header.length) +
                                       " bytes, above the limit of " + std::to_string(limits_.maxFileSize) +
                                       "; its data frames are dropped"));
        return outcomes;
    }
    bytes_.reserve(std::min<std::size_t>(header.length + 7, InitialReserve));
    reportProgress();
    if (header.length == 0)
        outcomes.push_back(complete());
    return outcomes;
}

std::vector<StreamOutcome> ConfigStreamReceiver::append(const cs2::ConfigDataStream& data) {
    bytes_.insert(bytes_.end(), data.data.begin(), data.data.end());
    reportProgress();
    if (bytes_.size() < header_.length)
        return {};
    return {complete()};
}

std::vector<StreamOutcome> ConfigStreamReceiver::stray(std::uint16_t hash) {
    if (state_ == State::Discarding && hash == hash_)
        return {};
    if (state_ == State::Finished && hash == hash_)
        return {fail(StreamErrorKind::MoreDataThanAnnounced, "a data frame arrived after the " +
                                                                 std::to_string(header_.length) +
                                                                 " announced bytes were complete; dropped")};
    state_ = State::Idle;
    hash_ = hash;
    header_ = {};
    key_.clear();
    bytes_.clear();
    return {
        fail(StreamErrorKind::DataWithoutHeader,
             "a data frame arrived without a header (DLC 6 or 7) before it; dropped up to the next header")};
}

StreamOutcome ConfigStreamReceiver::complete() {
    state_ = State::Finished;
    const std::uint16_t crc = cs2::crc16(bytes_);
    if (crc != header_.crc) {
        std::string what = "CRC mismatch: the header announces " + hex16(header_.crc) + ", the " +
                           std::to_string(bytes_.size()) + " received bytes give " + hex16(crc);
        const auto unpadded = std::span(bytes_).first(header_.length);
        if (unpadded.size() != bytes_.size() && cs2::crc16(unpadded) == header_.crc)
            what += " (the header's CRC covers the " + std::to_string(header_.length) +
                    " bytes without the zero padding)";
        return fail(StreamErrorKind::CrcMismatch, what);
    }
    ReceivedConfigFile file;
    file.key = key_;
    file.hash = hash_;
    file.broadcast = header_.form == Form::BroadcastHeader;
    file.broadcastValue = header_.extra;
    file.length = header_.length;
    file.crc = header_.crc;
    file.streamBytes = bytes_;
    return decodeFile(std::move(file));
}

// The format comes from the sender where it says so: a requested key's file is sent in the key's
// format (document 7.1). Only without a key (a broadcast, or no request seen) do the bytes decide: a
// payload that inflates is compressed; one that looks compressed but does not inflate is the plain
// file when it is text, and a damaged compressed file otherwise.
StreamOutcome ConfigStreamReceiver::decodeFile(ReceivedConfigFile file) const {
    const auto payload = std::span<const std::uint8_t>(file.streamBytes).first(file.length);
    const auto key = findConfigFileKey(file.key);
    const bool looksCompressed = payload::isCompressed(payload);
    if (key && key->format == StreamFormat::Binary) {
        file.contents.assign(payload.begin(), payload.end());
        return file;
    }
    if (looksCompressed && (!key || key->format == StreamFormat::Compressed)) {
        auto inflated = payload::inflate(payload, limits_.maxFileSize);
        if (inflated) {
            file.compressed = true;
            file.contents = std::move(*inflated);
            return file;
        }
        if (key || !payload::isText(payload))
            return ConfigStreamError{inflated.error().kind, describe() + ": " + inflated.error().message};
    }
    file.contents = payload::plainText(payload);
    return file;
}

ConfigStreamError ConfigStreamReceiver::fail(StreamErrorKind kind, const std::string& what) {
    ConfigStreamError error{kind, describe() + ": " + what};
    state_ = State::Discarding;
    return error;
}

std::string ConfigStreamReceiver::describe() const {
    std::string text = header_.form == Form::BroadcastHeader ? "broadcast stream" : "stream";
    if (!key_.empty())
        text += " for '" + key_ + "'";
    return text + " (hash " + hex16(hash_) + ")";
}

void ConfigStreamReceiver::reportProgress() const {
    if (onProgress_)
        onProgress_(progress());
}

} // namespace stellwerk::cs2config
