#pragma once

#include "base/Expected.h"

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::automation {

// One stop of a schedule: the block a train runs to (by its name on the track plan) and how long it stands
// there (milliseconds). blockId is filled in when the schedule is given to a train.
struct ScheduleStop {
    std::string block;
    std::int64_t dwellMs = 0;
    int blockId = 0;
};

// A train's timetable: its stops in order, run once or round and round. `next` is the stop it runs to
// (or stands at) now, so a run stopped and started again goes on where it was.
struct Schedule {
    std::vector<ScheduleStop> stops;
    bool loop = false;
    std::size_t next = 0;
    bool pushPull = false; // the train's own setting, kept in the same file (see Train::pushPull)

    bool done() const { return !loop && next >= stops.size(); }
    // On to the stop after the one reached.
    void advance() { next = loop && next + 1 >= stops.size() ? 0 : next + 1; }
};

// The schedule file, JSON: {"trains": [{"loc": "mfx:1", "loop": true, "next": 0, "pushPull": false,
//   "stops": [{"block": "Gleis 2", "dwell": 5}, ...]}]} with dwell in seconds (fractions allowed) and loc as
// the command line writes locomotives. Schedules by Loc-ID; the sentence says what is wrong.
Expected<std::map<std::uint32_t, Schedule>, std::string> parseSchedules(std::string_view json);
std::string schedulesJson(const std::map<std::uint32_t, Schedule>& schedules);

} // namespace stellwerk::automation
