#include "withrottleserver/WiThrottleClient.h"

#include <algorithm>

namespace stellwerk::withrottleserver {

QString WiThrottleClient::name() const {
    return QStringLiteral("withrottle ") + peer;
}

std::vector<ThrottleLoco*> WiThrottleClient::locos(char throttle, const std::string& key) {
    std::vector<ThrottleLoco*> found;
    const auto it = throttles.find(throttle);
    if (it == throttles.end())
        return found;
    for (ThrottleLoco& loco : it->second)
        if (key == "*" || loco.key == key)
            found.push_back(&loco);
    return found;
}

ThrottleLoco* WiThrottleClient::holding(char throttle, std::uint32_t locId) {
    const auto it = throttles.find(throttle);
    if (it == throttles.end())
        return nullptr;
    const auto loco = std::find_if(it->second.begin(), it->second.end(),
                                   [&](const ThrottleLoco& held) { return held.locId == locId; });
    return loco == it->second.end() ? nullptr : &*loco;
}

std::vector<std::pair<char, ThrottleLoco*>> WiThrottleClient::holdersOf(std::uint32_t locId) {
    std::vector<std::pair<char, ThrottleLoco*>> found;
    for (auto& [throttle, held] : throttles)
        for (ThrottleLoco& loco : held)
            if (loco.locId == locId)
                found.emplace_back(throttle, &loco);
    return found;
}

std::vector<std::pair<char, std::string>> WiThrottleClient::forget(std::uint32_t locId) {
    std::vector<std::pair<char, std::string>> keys;
    for (auto& [throttle, held] : throttles) {
        for (const ThrottleLoco& loco : held)
            if (loco.locId == locId)
                keys.emplace_back(throttle, loco.key);
        std::erase_if(held, [&](const ThrottleLoco& loco) { return loco.locId == locId; });
    }
    return keys;
}

bool WiThrottleClient::admit(qint64 nowMs, int perSecond) {
    if (nowMs - windowStartMs >= 1000) {
        windowStartMs = nowMs;
        linesInWindow = 0;
    }
    if (++linesInWindow <= perSecond)
        return true;
    ++limited;
    return false;
}

} // namespace stellwerk::withrottleserver
