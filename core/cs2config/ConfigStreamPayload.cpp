#include "cs2config/ConfigStreamPayload.h"

#include <algorithm>
#include <zlib.h>

namespace stellwerk::cs2config::payload {
namespace {

constexpr std::size_t SizePrefix = 4;
constexpr std::size_t FrameBytes = 8;
constexpr std::size_t MinChunk = 4096;

std::size_t paddingAfter(std::size_t newline) {
    return (FrameBytes - (newline + 1) % FrameBytes) % FrameBytes;
}

ConfigStreamError inflateError(StreamErrorKind kind, std::string message) {
    return ConfigStreamError{kind, std::move(message)};
}

// Runs inflate() over `in` into `out`, growing `out` geometrically up to `ceiling` bytes.
// Returns the zlib status of the last call.
int inflateInto(z_stream& zs, std::string& out, std::size_t ceiling) {
    std::size_t used = 0;
    int status = Z_OK;
    while (status == Z_OK) {
        if (used == out.size()) {
            if (out.size() >= ceiling)
                break;
            out.resize(std::min(ceiling, std::max(MinChunk, out.size() * 2)));
        }
        zs.next_out = reinterpret_cast<Bytef*>(out.data() + used);
        zs.avail_out = uInt(out.size() - used);
        status = ::inflate(&zs, Z_NO_FLUSH);
        used = out.size() - zs.avail_out;
    }
    out.resize(used);
    return status;
}

} // namespace

bool isCompressed(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < SizePrefix + 2)
        return false;
    const unsigned cmf = bytes[SizePrefix], flg = bytes[SizePrefix + 1];
    return cmf == 0x78 && (cmf * 256 + flg) % 31 == 0;
}

std::uint32_t announcedSize(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < SizePrefix)
        return 0;
    return (std::uint32_t(bytes[0]) << 24) | (std::uint32_t(bytes[1]) << 16) |
           (std::uint32_t(bytes[2]) << 8) | bytes[3];
}

std::vector<std::uint8_t> compress(std::string_view contents) {
    uLongf size = compressBound(uLong(contents.size()));
    std::vector<std::uint8_t> out(SizePrefix + size);
    const auto length = std::uint32_t(contents.size());
    out[0] = std::uint8_t(length >> 24), out[1] = std::uint8_t(length >> 16);
    out[2] = std::uint8_t(length >> 8), out[3] = std::uint8_t(length);
    compress2(out.data() + SizePrefix, &size, reinterpret_cast<const Bytef*>(contents.data()),
              uLong(contents.size()), Z_DEFAULT_COMPRESSION);
    out.resize(SizePrefix + size);
    return out;
}

Expected<std::string, ConfigStreamError> inflate(std::span<const std::uint8_t> bytes, std::size_t limit) {
    if (bytes.size() < SizePrefix)
        return inflateError(StreamErrorKind::InflateFailed, "the payload has " +
                                                                std::to_string(bytes.size()) +
                                                                " bytes, fewer than its 4-byte size prefix");
    const std::size_t announced = announcedSize(bytes);
    if (announced > limit)
        return inflateError(StreamErrorKind::TooLarge, "the file announces " + std::to_string(announced) +
                                                           " bytes, above the limit of " +
                                                           std::to_string(limit));
    z_stream zs{};
    if (inflateInit(&zs) != Z_OK)
        return inflateError(StreamErrorKind::InflateFailed, "zlib could not start inflating");
    zs.next_in = const_cast<Bytef*>(bytes.data() + SizePrefix);
    zs.avail_in = uInt(bytes.size() - SizePrefix);
    std::string out;
    const int status = inflateInto(zs, out, announced + 1);
    const std::string zlibMessage = zs.msg ? zs.msg : "";
    inflateEnd(&zs);
    if (out.size() > announced)
        return inflateError(StreamErrorKind::SizeMismatch, "the file inflates to more than the " +
                                                               std::to_string(announced) +
                                                               " bytes its size prefix announces");
    if (status == Z_NEED_DICT)
        return inflateError(StreamErrorKind::InflateFailed, "the zlib stream needs a preset dictionary");
    if (status != Z_STREAM_END)
        return inflateError(StreamErrorKind::InflateFailed,
                            zlibMessage.empty() ? "the zlib stream ends early after " +
                                                      std::to_string(out.size()) + " inflated bytes"
                                                : "the zlib stream is damaged: " + zlibMessage);
    if (out.size() != announced)
        return inflateError(StreamErrorKind::SizeMismatch,
                            "the file inflates to " + std::to_string(out.size()) +
                                " bytes, its size prefix announces " + std::to_string(announced));
    return out;
}

bool isText(std::span<const std::uint8_t> bytes) {
    std::size_t end = bytes.size();
    while (end > 0 && bytes[end - 1] == 0)
        --end;
    return std::all_of(bytes.begin(), bytes.begin() + std::ptrdiff_t(end), [](std::uint8_t byte) {
        return byte >= 0x20 ? byte != 0x7F : byte == '\t' || byte == '\n' || byte == '\r';
    });
}

std::string padLines(std::string_view text) {
    std::string out;
    out.reserve(text.size() + text.size() / 4);
    for (char c : text) {
        out += c;
        if (c == '\n')
            out.append(paddingAfter(out.size() - 1), ' ');
    }
    return out;
}

bool hasPaddedLines(std::string_view text) {
    for (std::size_t i = text.find('\n'); i != std::string_view::npos; i = text.find('\n', i + 1)) {
        const std::size_t end = std::min(text.size(), i + 1 + paddingAfter(i));
        for (std::size_t j = i + 1; j < end; ++j)
            if (text[j] != ' ')
                return false;
    }
    return true;
}

std::string stripLinePadding(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    std::size_t line = 0;
    for (std::size_t i = text.find('\n'); i != std::string_view::npos; i = text.find('\n', line)) {
        out.append(text.substr(line, i + 1 - line));
        line = std::min(text.size(), i + 1 + paddingAfter(i));
    }
    out.append(text.substr(line));
    return out;
}

std::string plainText(std::span<const std::uint8_t> bytes) {
    const std::string_view all(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::string_view text = all;
    if (all.size() % FrameBytes == 0) { // a CS3 counts the frame padding in the length
        const auto last = all.find_last_not_of('\0');
        text = all.substr(0, last == std::string_view::npos ? 0 : last + 1);
    }
    if (text.find('\0') != std::string_view::npos)
        return std::string(all); // binary: its zeros are data
    return hasPaddedLines(text) ? stripLinePadding(text) : std::string(text);
}

} // namespace stellwerk::cs2config::payload
