#pragma once

// What a test client of one of the servers has read, as the codec's variant of messages: every one of a kind,
// the last one, and waiting for one (the Z21 and WiThrottle test clients both keep theirs here).

#include <QTest>
#include <optional>
#include <variant>
#include <vector>

namespace stellwerk::support {

template <class Message>
class ReceivedMessages {
public:
    template <class T>
    std::vector<T> all() const {
        std::vector<T> found;
        for (const Message& message : received)
            if (const T* one = std::get_if<T>(&message))
                found.push_back(*one);
        return found;
    }
    template <class T>
    std::optional<T> last() const {
        const std::vector<T> found = all<T>();
        return found.empty() ? std::nullopt : std::optional<T>(found.back());
    }
    template <class T>
    bool waitFor(int timeoutMs = 5000) {
        return QTest::qWaitFor([&] { return last<T>().has_value(); }, timeoutMs);
    }

    std::vector<Message> received;
};

} // namespace stellwerk::support
