#pragma once

#include "cs2/Messages.h"

#include <utility>

namespace stellwerk::cs2 {

// A command as we send it: default priority, no response bit, hash 0. Callers name the body only; the
// station session stamps its own hash on every frame it sends.
inline Message request(MessageBody body) {
    return {0, false, 0, std::move(body)};
}

// A status we announce (a state, not a command): default priority, the response bit set, hash 0, as the
// status answers of chapter 9 are sent.
inline Message announcement(MessageBody body) {
    return {0, true, 0, std::move(body)};
}

} // namespace stellwerk::cs2
