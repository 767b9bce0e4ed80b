#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `stellwerk-cli stream decode [FILE] [-d DIR]`: reads frames (one per line, any notation the
// decoder reads; FILE or standard input), writes every complete config-data stream as a file into
// DIR (default: the current directory), named after the requested key when a request preceded it
// (lokomotive.cs2, gbs-0.cs2, ...) and stream-<n>.cs2/.bin otherwise, and prints one line per
// stream. Returns 0 when every stream was intact, 1 when one was broken or a file could not be
// written, 2 on a usage error.
//
// `stellwerk-cli stream encode FILE --key KEY [--follow-up TEXT] [--hash 0x4711] [--broadcast]
// [--notation document|candump]`: prints the frames a CS2 sends for FILE: the request's
// acknowledgement and the stream to the requester's hash, or with --broadcast the "configuration
// changed" stream under the sender's hash. Returns 0, 1 when FILE cannot be read, 2 on a usage error.
int runStream(const std::vector<std::string>& arguments, std::istream& in, std::ostream& out,
              std::ostream& err);

} // namespace stellwerk::cli
