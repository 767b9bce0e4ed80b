#include "transport/NetworkFraming.h"

namespace stellwerk::transport {

using can::CanFrame;

QByteArray encodeFrames(std::span<const CanFrame> frames) {
    QByteArray bytes;
    bytes.reserve(qsizetype(frames.size() * CanFrame::NetworkSize));
    for (const CanFrame& frame : frames) {
        const auto network = frame.toNetwork();
        bytes.append(reinterpret_cast<const char*>(network.data()), qsizetype(network.size()));
    }
    return bytes;
}

bool appendFrame(std::span<const std::uint8_t, CanFrame::NetworkSize> bytes, std::vector<CanFrame>& out) {
    const CanFrame frame = CanFrame::fromNetwork(bytes);
    if (!frame.isWellFormed())
        return false;
    out.push_back(frame);
    return true;
}

DatagramContent decodeDatagram(std::span<const std::uint8_t> datagram, std::vector<CanFrame>& out) {
    DatagramContent content;
    if (datagram.empty() || datagram.size() % CanFrame::NetworkSize != 0)
        return content;
    content.wholeFrames = true;
    for (std::size_t at = 0; at < datagram.size(); at += CanFrame::NetworkSize) {
        if (appendFrame(datagram.subspan(at).first<CanFrame::NetworkSize>(), out))
            ++content.frames;
        else
            ++content.malformed;
    }
    return content;
}

} // namespace stellwerk::transport
