#include "cs2/Hash.h"

namespace stellwerk::cs2 {

std::uint16_t hashFromUid(std::uint32_t uid) {
    const std::uint16_t x = std::uint16_t((uid >> 16) ^ (uid & 0xFFFF));
    return std::uint16_t(((x << 3) & 0xFF00) | 0x0300 | (x & 0x7F));
}

bool hashIsStreamPosition(const CanFrame& frame) {
    const auto command = Command(cs2::command(frame));
    if (command == Command::ConfigDataStream || command == Command::Connect6021Stream)
        return true;
    if (command == Command::BootloaderCan && !cs2::isResponse(frame) && frame.dlc == 8)
        return true; // firmware block data: hash = 0x0300 + frame index
    return command == Command::StatusDataConfig && cs2::isResponse(frame) && frame.dlc != 5 && frame.dlc != 6;
}

HashGuard::HashGuard(std::uint32_t uid) : uid_(uid), hash_(hashFromUid(uid)) {}

bool HashGuard::observe(const CanFrame& frame) {
    if (hashIsStreamPosition(frame))
        return false;
    seen_.set(cs2::hash(frame));
    return cs2::hash(frame) == hash_ && !cs2::isResponse(frame);
}

std::uint16_t HashGuard::chooseNewHash() {
    // Walk a deterministic sequence of UID variations until one gives a hash nobody uses.
    for (std::uint32_t i = 0; i < 65536; ++i) {
        ++attempt_;
        const std::uint16_t candidate = hashFromUid(uid_ ^ (attempt_ * 0x9E3779B1u));
        if (candidate != hash_ && !seen_.test(candidate)) {
            hash_ = candidate;
            return hash_;
        }
    }
    return hash_;
}

} // namespace stellwerk::cs2
