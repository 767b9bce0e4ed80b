#include "cs2config/RouteDelay.h"

#include "cs2config/Values.h"

namespace stellwerk::cs2config {

namespace {

constexpr std::size_t maxWholeDigits = 8;
constexpr std::size_t maxDecimals = 3;

bool allDigits(std::string_view text) {
    for (char c : text)
        if (c < '0' || c > '9')
            return false;
    return true;
}

std::int64_t digitsValue(std::string_view text) {
    std::int64_t value = 0;
    for (char c : text)
        value = value * 10 + (c - '0');
    return value;
}

} // namespace

std::optional<std::int64_t> parseRouteDelay(std::string_view text) {
    text = trimmed(text);
    const std::size_t point = text.find('.');
    const std::string_view whole = text.substr(0, point);
    const std::string_view decimals =
        point == std::string_view::npos ? std::string_view() : text.substr(point + 1);
    if (whole.empty() || whole.size() > maxWholeDigits || !allDigits(whole))
        return std::nullopt;
    if (point != std::string_view::npos &&
        (decimals.empty() || decimals.size() > maxDecimals || !allDigits(decimals)))
        return std::nullopt;
    std::int64_t fraction = digitsValue(decimals);
    for (std::size_t i = decimals.size(); i < maxDecimals; ++i)
        fraction *= 10;
    return digitsValue(whole) * 1000 + fraction;
}

std::string formatRouteDelay(std::int64_t milliseconds) {
    if (milliseconds < 0)
        milliseconds = 0;
    std::string text = std::to_string(milliseconds / 1000);
    std::int64_t fraction = milliseconds % 1000;
    if (fraction == 0)
        return text;
    std::string decimals = std::to_string(fraction);
    decimals.insert(0, maxDecimals - decimals.size(), '0');
    while (decimals.back() == '0')
        decimals.pop_back();
    return text + "." + decimals;
}

} // namespace stellwerk::cs2config
