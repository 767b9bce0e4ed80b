#pragma once

#include "operation/TrainBook.h"

#include <filesystem>
#include <string>

namespace stellwerk::model {
class LayoutInUse;
}

namespace stellwerk::operation {

// Where a layout's book of trains is kept, and reading and writing it so that nothing is lost: a file that
// cannot be read is put aside (renamed, never overwritten) and the trains start unplaced, with a sentence.
class TrainBookFile {
public:
    explicit TrainBookFile(std::filesystem::path path) : path_(std::move(path)) {}

    // An opened folder: stellwerk-trains.json in the layout folder holding config/ (in the program's data
    // folder, under trains/, when that folder cannot be written). The station's download: in the data
    // folder, trains/station-<station>.json, <station> its address ("simulated" for the built-in one).
    // Empty while no layout is in use.
    static std::filesystem::path placeFor(const model::LayoutInUse& layout,
                                          const std::filesystem::path& dataDir, const std::string& station);

    const std::filesystem::path& path() const { return path_; }
    // The book in the file (empty when there is none yet); `problem` says what went wrong, and where the
    // unreadable file was put aside.
    TrainBook load(std::string& problem);
    // Empty when written; else why not (never over a damaged file that could not be put aside).
    std::string save(const TrainBook& book) const;

private:
    std::filesystem::path path_;
    bool damagedInPlace_ = false;
};

} // namespace stellwerk::operation
