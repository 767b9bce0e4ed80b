#pragma once

#include "automation/Schedule.h"
#include "base/Expected.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::operation {

// One train of the book: the locomotive, its length and push-pull setting, where its front stood and which
// end it faced, whether the automation drove it, and its schedule (no stops: none).
struct BookedTrain {
    std::uint32_t locId = 0;
    int lengthMm = 200;
    bool pushPull = false;
    std::string block; // the block's name on the track plan
    int blockId = 0;   // and its number in the graph, taken when it still bears that name
    trackgraph::End towards = trackgraph::End::B;
    bool automatic = false; // resumed by the user's Resume, never by itself
    automation::Schedule schedule;
};

// The trains of one layout, kept between runs so that they are placed again where they stood and their
// schedules go on with the stop they had not reached. JSON:
// {"version": 1, "trains": [{"loc": 16385, "length": 200, "pushPull": false, "block": "Gleis 1",
//   "blockId": 3, "towards": "b", "automatic": false,
//   "schedule": {"loop": true, "next": 0, "stops": [{"block": "Gleis 2", "dwell": 5}]}}]}
class TrainBook {
public:
    const std::vector<BookedTrain>& trains() const { return trains_; }
    const BookedTrain* find(std::uint32_t locId) const;
    BookedTrain* find(std::uint32_t locId);
    // Adds the train, or replaces the one of the same locomotive.
    void put(BookedTrain train);
    void remove(std::uint32_t locId);
    bool empty() const { return trains_.empty(); }

    std::string toJson() const;
    // The sentence says what is wrong.
    static Expected<TrainBook, std::string> fromJson(std::string_view json);

private:
    std::vector<BookedTrain> trains_;
};

} // namespace stellwerk::operation
