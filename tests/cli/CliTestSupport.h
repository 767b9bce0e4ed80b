#pragma once

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

// What the cli command tests share: a command's result, the corpus files and reading what a command wrote.
namespace stellwerk::cli::test {

// A command's exit status and what it wrote to stdout and stderr.
struct Outcome {
    int status;
    std::string out;
    std::string err;
};

// The path of a corpus file, read in place from ../shared/corpus; the test fails (not skips) when it
// is missing.
inline std::string corpus(const std::string& relative) {
    const std::string path = std::string(STELLWERK_SHARED_DIR) + "/corpus/" + relative;
    EXPECT_TRUE(std::filesystem::exists(path)) << "corpus file missing: " << path;
    return path;
}

// The bytes of a file (empty when it cannot be read).
inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

} // namespace stellwerk::cli::test
