#pragma once

#include "cs2config/TrackLayout.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::sim {

// Where a train goes at the end of a feedback section in one direction of travel: on to `next`, or to
// `diverging` when a facing turnout in front of it lies in `divergingPosition`.
struct SectionExit {
    static constexpr int BufferStop = -1;

    int next = BufferStop;              // section index; BufferStop: the track ends here
    std::uint32_t turnout = 0;          // Loc-ID of the facing turnout that decides the way; 0 = none
    std::uint8_t divergingPosition = 0; // the turnout position leading to `diverging` (0 = round/red)
    int diverging = BufferStop;
};

// One stretch of track watched by an S88 contact, as the train movement sees it.
struct FeedbackSection {
    std::string name;
    std::uint16_t device = 0;  // the feedback device (Link-S88) reporting the contact
    std::uint16_t contact = 0; // contact number on that device
    int lengthMm = 1000;       // model length
    SectionExit ahead;         // travelling "ahead" (a loco placed forward runs this way)
    SectionExit behind;        // travelling the other way
};

// Where a locomotive stands when the simulation starts: its front end `offsetMm` into a section,
// facing "ahead" when it runs forward.
struct TrainPlacement {
    std::uint32_t locId = 0;
    int section = 0;
    int offsetMm = 0;
};

// The track of a layout reduced to what moving trains need: feedback sections, how they join (with the
// turnouts that choose between branches) and where the locomotives stand.
struct TrainTrack {
    std::vector<FeedbackSection> sections;
    std::vector<TrainPlacement> placements;

    // The index of the section with this name, or nullopt.
    std::optional<int> find(std::string_view name) const;
    // True when every link points at an existing section and every placement is on one.
    bool consistent() const;

    // The demo layout's track (resources/demo-layout): a station with a passing track behind turnouts
    // W1/W2, a dead-end siding behind W3, and an open line returning to the station.
    static TrainTrack demo();
    // Any other layout: its s88 contact tiles, in page, row and column order, joined into one loop, with
    // up to three of `locIds` spread over it.
    static TrainTrack loopOfContacts(const cs2config::TrackLayout& layout,
                                     const std::vector<std::uint32_t>& locIds);
};

} // namespace stellwerk::sim
