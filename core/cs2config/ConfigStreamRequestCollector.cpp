#include "cs2config/ConfigStreamRequestCollector.h"

#include <algorithm>

namespace stellwerk::cs2config {

std::optional<CollectedConfigRequest> ConfigRequestCollector::feed(const cs2::Message& message) {
    const auto* body = std::get_if<cs2::ConfigDataRequest>(&message.body);
    if (!body)
        return std::nullopt;
    const auto pending = std::find_if(pending_.begin(), pending_.end(), [&](const Pending& p) {
        return p.hash == message.hash && p.response == message.response;
    });
    if (pending != pending_.end())
        return add(pending, body->text());
    return start(std::string(body->text()), message.hash, message.response);
}

std::optional<CollectedConfigRequest> ConfigRequestCollector::start(std::string key, std::uint16_t hash,
                                                                    bool response) {
    auto request = ConfigRequest::forKey(key);
    if (!request)
        return std::nullopt; // an empty key: nothing was asked for
    if (request->followUpFrames() == 0)
        return CollectedConfigRequest{*request, hash, response};
    pending_.push_back({hash, response, std::move(key), {}, request->followUpFrames()});
    return std::nullopt;
}

std::optional<CollectedConfigRequest> ConfigRequestCollector::add(std::vector<Pending>::iterator pending,
                                                                  std::string_view text) {
    pending->qualifier += text;
    if (--pending->missing > 0)
        return std::nullopt;
    const Pending done = *pending;
    pending_.erase(pending);
    auto request = ConfigRequest::forKey(done.key, done.qualifier);
    if (!request)
        return std::nullopt;
    return CollectedConfigRequest{*request, done.hash, done.response};
}

} // namespace stellwerk::cs2config
