// Helpers of the Z21 codec tests: a datagram from its bytes, and the one request it must hold.
#pragma once

#include "z21/ReplyCodec.h"
#include "z21/RequestCodec.h"

#include <cstdint>
#include <gtest/gtest.h>
#include <vector>

namespace stellwerk::z21::test {

using Bytes = std::vector<std::uint8_t>;

// The single request of a datagram that must hold exactly one and no error.
inline Request onlyRequest(const Bytes& datagram) {
    const DatagramRequests read = readRequests(datagram);
    EXPECT_TRUE(read.errors.empty()) << (read.errors.empty() ? "" : read.errors.front().detail);
    EXPECT_EQ(read.requests.size(), 1u);
    return read.requests.empty() ? Request{UnknownRequest{}} : read.requests.front();
}

template <class T>
T onlyRequestOf(const Bytes& datagram) {
    const Request request = onlyRequest(datagram);
    EXPECT_FALSE(request.wrongChecksum);
    EXPECT_TRUE(std::holds_alternative<T>(request.body)) << "variant index " << request.body.index();
    return std::holds_alternative<T>(request.body) ? std::get<T>(request.body) : T{};
}

template <class T>
T onlyReplyOf(const Bytes& datagram) {
    const DatagramReplies read = readReplies(datagram);
    EXPECT_TRUE(read.errors.empty());
    EXPECT_EQ(read.replies.size(), 1u);
    if (read.replies.empty() || !std::holds_alternative<T>(read.replies.front()))
        return T{};
    return std::get<T>(read.replies.front());
}

} // namespace stellwerk::z21::test
