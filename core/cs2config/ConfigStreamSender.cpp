#include "cs2config/ConfigStreamSender.h"

#include "cs2/Codec.h"
#include "cs2/Crc16.h"
#include "cs2config/ConfigStreamPayload.h"

#include <algorithm>

namespace stellwerk::cs2config {
namespace {

using Form = cs2::ConfigDataStream::Form;

constexpr std::size_t FrameBytes = 8;

can::CanFrame streamFrame(const cs2::ConfigDataStream& body, std::uint16_t hash) {
    return cs2::encode(cs2::Message{0, false, hash, body});
}

cs2::ConfigDataStream header(std::size_t length, std::uint16_t crc, const StreamAddress& address) {
    cs2::ConfigDataStream body;
    body.form = address.broadcastValue ? Form::BroadcastHeader : Form::Header;
    body.length = std::uint32_t(length);
    body.crc = crc;
    body.extra = address.broadcastValue.value_or(0);
    return body;
}

} // namespace

std::vector<std::uint8_t> streamPayload(std::string_view contents, StreamFormat format) {
    if (format == StreamFormat::Compressed)
        return payload::compress(contents);
    const std::string text =
        format == StreamFormat::Ms2Text ? payload::padLines(contents) : std::string(contents);
    return std::vector<std::uint8_t>(text.begin(), text.end());
}

std::vector<can::CanFrame> payloadFrames(std::span<const std::uint8_t> payload, StreamAddress address) {
    std::vector<std::uint8_t> bytes(payload.begin(), payload.end());
    bytes.resize((payload.size() + FrameBytes - 1) / FrameBytes * FrameBytes, 0);

    std::vector<can::CanFrame> frames;
    frames.reserve(1 + bytes.size() / FrameBytes);
    frames.push_back(streamFrame(header(payload.size(), cs2::crc16(bytes), address), address.hash));
    cs2::ConfigDataStream data;
    for (std::size_t at = 0; at < bytes.size(); at += FrameBytes) {
        std::copy_n(bytes.begin() + std::ptrdiff_t(at), FrameBytes, data.data.begin());
        frames.push_back(streamFrame(data, address.hash));
    }
    return frames;
}

std::vector<can::CanFrame> streamFrames(std::string_view contents, StreamFormat format,
                                        StreamAddress address) {
    return payloadFrames(streamPayload(contents, format), address);
}

std::vector<can::CanFrame> answerFrames(const ConfigRequest& request, std::string_view contents,
                                        std::uint16_t requesterHash) {
    std::vector<can::CanFrame> frames = request.frames(requesterHash, true);
    const auto stream =
        streamFrames(contents, streamFormatForKey(request.key()), StreamAddress::reply(requesterHash));
    frames.insert(frames.end(), stream.begin(), stream.end());
    return frames;
}

StreamFormat streamFormatForKey(std::string_view key) {
    const auto row = findConfigFileKey(key);
    return row ? row->format : StreamFormat::Compressed;
}

} // namespace stellwerk::cs2config
