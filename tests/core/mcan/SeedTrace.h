#pragma once

// Reads the chapter-11 "Telegramm Trace" of the M-CAN seed documents in place (../shared/seeds): the ids
// are printed in binary (prio, two bytes of the handle, cmd, node), then the DLC and the data in hex.

#include "can/CanFrame.h"

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace stellwerk::seeds {

inline std::string seedPath(const std::string& name) {
    return std::string(STELLWERK_SHARED_DIR) + "/seeds/" + name;
}

inline const std::string McanSeed000 = "000_1fe028ff65ffc99e.txt";
inline const std::string McanSeed002 = "002_ee1b034087bd9111.txt";

// The frames of chapter 11, in the document's order; empty when the file cannot be read.
inline std::vector<can::CanFrame> chapter11Trace(const std::string& seed) {
    std::ifstream in(seedPath(seed));
    std::vector<can::CanFrame> frames;
    const std::regex row(
        R"(^\s*([01]{3})\s+([01]{8})\s+([01]{8})\s+([01]{3})\s+([01]{7})\s+([0-8])((?:\s+[0-9A-Fa-f]{2})*))");
    bool inTrace = false;
    for (std::string line; std::getline(in, line);) {
        if (line.find("wird der Telegramm Trace einer MS1") != std::string::npos)
            inTrace = true;
        std::smatch m;
        if (!inTrace || !std::regex_search(line, m, row))
            continue;
        const std::string bits = m[1].str() + m[2].str() + m[3].str() + m[4].str() + m[5].str();
        can::CanFrame frame;
        frame.id = std::uint32_t(std::stoul(bits, nullptr, 2));
        frame.dlc = std::uint8_t(std::stoi(m[6].str()));
        std::istringstream data(m[7].str());
        std::string byte;
        for (std::size_t i = 0; i < frame.dlc && data >> byte; ++i)
            frame.data[i] = std::uint8_t(std::stoul(byte, nullptr, 16));
        frames.push_back(frame);
    }
    return frames;
}

} // namespace stellwerk::seeds
