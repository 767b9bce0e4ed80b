#pragma once

// The offline commands run in-process as the CLI tests call them: decode, encode and cs2 with their
// arguments (and decode's standard input), each giving its exit status and what it wrote.

#include "CliTestSupport.h"
#include "Cs2Command.h"
#include "DecodeCommand.h"
#include "EncodeCommand.h"

#include <sstream>
#include <string>
#include <vector>

namespace stellwerk::cli::test {

inline Outcome decode(std::vector<std::string> arguments, const std::string& input = {}) {
    std::istringstream in(input);
    std::ostringstream out, err;
    const int status = runDecode(arguments, in, out, err);
    return {status, out.str(), err.str()};
}

inline Outcome encode(std::vector<std::string> arguments) {
    std::ostringstream out, err;
    const int status = runEncode(arguments, out, err);
    return {status, out.str(), err.str()};
}

inline Outcome cs2Command(std::vector<std::string> arguments) {
    std::ostringstream out, err;
    const int status = runCs2(arguments, out, err);
    return {status, out.str(), err.str()};
}

} // namespace stellwerk::cli::test
