#include "station/StationIdentity.h"

#include <QRandomGenerator>

namespace stellwerk::station {
namespace {

std::uint32_t randomUid() {
    // Avoid 0 (broadcast) and the Loc-ID ranges below 0x10000 so that the UID is a device UID.
    return 0x10000u + QRandomGenerator::global()->bounded(0xFFFEFFFFu);
}

} // namespace

StationIdentity::StationIdentity(std::optional<std::uint32_t> uid)
    : uid_(uid.value_or(randomUid())), guard_(uid_) {}

can::CanFrame StationIdentity::stamp(can::CanFrame frame) {
    frame.id = (frame.id & ~std::uint32_t(0xFFFF)) | guard_.hash();
    sent_[sentCount_++ % EchoMemory] = frame;
    return frame;
}

std::optional<std::uint16_t> StationIdentity::observe(const can::CanFrame& frame) {
    if (!guard_.observe(frame) || isOwnEcho(frame))
        return std::nullopt;
    return guard_.chooseNewHash();
}

bool StationIdentity::isOwnEcho(const can::CanFrame& frame) const {
    const std::size_t count = std::min(sentCount_, EchoMemory);
    for (std::size_t i = 0; i < count; ++i)
        if (sent_[i] == frame)
            return true;
    return false;
}

} // namespace stellwerk::station
