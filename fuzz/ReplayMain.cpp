// A main() for the fuzz targets in the normal (gcc) build: runs every file of the given folders through
// the target once, so that the targets keep compiling and their seeds keep passing their invariants in
// every CI run. "--prefix=N" puts byte N before the files that follow (the targets' choice byte).
#include "FuzzSupport.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

int replay(const fs::path& file, const std::optional<char>& prefix) {
    std::ifstream in(file, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), {}};
    if (prefix)
        bytes.insert(bytes.begin(), *prefix);
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    std::optional<char> prefix;
    int inputs = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument.rfind("--prefix=", 0) == 0) {
            prefix = static_cast<char>(std::stoi(argument.substr(9)));
            continue;
        }
        std::error_code error;
        if (!fs::is_directory(argument, error)) {
            std::fprintf(stderr, "replay: %s is not a folder\n", argument.c_str());
            return 2;
        }
        for (const auto& entry : fs::recursive_directory_iterator(argument))
            if (entry.is_regular_file())
                inputs += replay(entry.path(), prefix);
    }
    std::printf("replayed %d inputs without a finding\n", inputs);
    return inputs > 0 ? 0 : 1;
}
