#pragma once

// The simulated station with trains on the track graph, as the train tests drive it: a station with track
// power on, the movement with the trains placed, a recorder of the S88 events and of the accidents, and
// the clock run in 100 ms steps. Layouts: the demo, a folder (the corpus) or pages drawn in a test.

#include "SimTestSupport.h"
#include "TrackGraphTestSupport.h"
#include "cs2config/TrackPage.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/TrainMovement.h"

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace stellwerk::sim::test {

using namespace std::chrono_literals;

// A layout of pages drawn in a test (trackgraph::test::DrawnPage), with locomotives and accessories as
// lokomotive.cs2 and magnetartikel.cs2 text (empty: none).
inline StationLayout drawnLayout(const std::vector<trackgraph::test::DrawnPage>& pages,
                                 const std::string& locomotives = {}, const std::string& accessories = {}) {
    StationLayout::Files files;
    std::string index = "[gleisbild]\nversion\n .major=1\n";
    for (const trackgraph::test::DrawnPage& drawn : pages) {
        const trackgraph::SourcePage source = drawn.source();
        index += "seite\n" + (source.id != 0 ? " .id=" + std::to_string(source.id) + "\n" : std::string()) +
                 " .name=" + source.name + "\n";
        cs2config::TrackPage page;
        page.elements = *source.elements;
        files["gleisbilder/" + source.name + ".cs2"] = page.write().serialize();
    }
    files["gleisbild.cs2"] = index;
    if (!locomotives.empty())
        files["lokomotive.cs2"] = locomotives;
    if (!accessories.empty())
        files["magnetartikel.cs2"] = accessories;
    return StationLayout::fromFiles(std::move(files));
}

// lokomotive.cs2 text with these locomotives (Loc-ID, name).
inline std::string locomotivesFile(const std::vector<std::pair<std::uint32_t, std::string>>& locos) {
    std::string text = "[lokomotive]\nversion\n .minor=3\n";
    for (const auto& [locId, name] : locos)
        text += "lokomotive\n .name=" + name + "\n .uid=0x" + QString::number(locId, 16).toStdString() + "\n";
    return text;
}

// One layout's station and trains.
class TrainRig {
public:
    explicit TrainRig(StationLayout layout)
        : station(std::move(layout), {.power = SimulatedStation::Power::Running}), contacts(station) {}

    // Places the trains and starts the movement with its clock stopped (the tests run it).
    void place(std::vector<TrainPlacement> placements) {
        movement = std::make_unique<TrainMovement>(station, std::move(placements));
        QObject::connect(movement.get(), &TrainMovement::accident,
                         [this](const Accident& accident) { accidents.push_back(accident.text); });
        movement->start();
        movement->stop();
    }
    // Simulated time in 100 ms steps.
    void run(std::chrono::milliseconds duration) {
        for (auto elapsed = 0ms; elapsed < duration; elapsed += 100ms)
            movement->advance(100ms);
    }
    void drive(std::uint32_t locId, std::uint16_t speed) { station.receive(test::speed(locId, speed)); }
    void reverse(std::uint32_t locId) { station.receive(test::direction(locId, cs2::Direction::Backward)); }
    // Sets a turnout (keyboard number, MM) as a controller does, and lets it settle.
    void setTurnout(std::uint32_t keyboard, std::uint8_t position) {
        station.receive(test::switchAccessory(0x3000 + keyboard - 1, position));
    }
    // The contacts switched on, in order.
    std::vector<std::uint16_t> reached() const {
        std::vector<std::uint16_t> on;
        for (const ContactEvent& event : contacts.events)
            if (event.occupied)
                on.push_back(event.contact);
        return on;
    }
    const TrainPosition& at(std::uint32_t locId) {
        last_ = movement->position(locId).value_or(TrainPosition{});
        return last_;
    }
    std::string blockName(int block) const {
        return block == 0 ? std::string("(between blocks)") : movement->graph().block(block).name;
    }

    SimulatedStation station;
    ContactRecorder contacts;
    std::unique_ptr<TrainMovement> movement;
    std::vector<std::string> accidents;

private:
    TrainPosition last_;
};

} // namespace stellwerk::sim::test
