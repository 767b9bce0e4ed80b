#pragma once

// Helpers shared by the config-data stream tests: frames from text, corpus logs, and feeding frames
// to a receiver.

#include "../cs2/TestSupport.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2config/ConfigStreamReceiver.h"

#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config::test {

using cs2::test::corpusFile;
using cs2::test::frame;

// Every frame of a logged capture (any notation parseFrame reads); fails the test on a bad line.
inline std::vector<can::CanFrame> framesOfLog(std::string_view corpusPath) {
    std::ifstream in(corpusFile(corpusPath));
    std::vector<can::CanFrame> frames;
    std::string line;
    while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos)
            frames.push_back(frame(line));
    return frames;
}

// Feeds every frame and returns everything the receiver finished, then what finish() adds.
inline std::vector<StreamOutcome> receiveAll(ConfigStreamReceiver& receiver,
                                             const std::vector<can::CanFrame>& frames) {
    std::vector<StreamOutcome> outcomes;
    for (const auto& f : frames)
        for (auto& outcome : receiver.feed(f))
            outcomes.push_back(std::move(outcome));
    if (auto last = receiver.finish())
        outcomes.push_back(std::move(*last));
    return outcomes;
}

inline std::vector<StreamOutcome> receiveAll(const std::vector<can::CanFrame>& frames,
                                             StreamLimits limits = {}) {
    ConfigStreamReceiver receiver(limits);
    return receiveAll(receiver, frames);
}

// The single outcome of a stream, which must be a good file.
inline ReceivedConfigFile singleFile(const std::vector<StreamOutcome>& outcomes) {
    EXPECT_EQ(outcomes.size(), 1u);
    if (outcomes.size() != 1)
        return {};
    EXPECT_TRUE(outcomes[0].hasValue()) << (outcomes[0] ? "" : outcomes[0].error().message);
    return outcomes[0] ? outcomes[0].value() : ReceivedConfigFile{};
}

// The single outcome of a stream, which must be an error.
inline ConfigStreamError singleError(const std::vector<StreamOutcome>& outcomes) {
    EXPECT_EQ(outcomes.size(), 1u);
    if (outcomes.size() != 1 || outcomes[0].hasValue()) {
        ADD_FAILURE() << "expected exactly one error";
        return {StreamErrorKind::Incomplete, ""};
    }
    return outcomes[0].error();
}

inline std::vector<std::uint8_t> bytesOf(std::string_view text) {
    return {text.begin(), text.end()};
}

} // namespace stellwerk::cs2config::test
