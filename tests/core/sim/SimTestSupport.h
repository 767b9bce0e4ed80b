#pragma once

// Helpers for the simulated station tests: a small inline layout, frames written as the protocol
// document writes them, and a probe that sends one frame and returns the station's answer.

#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "sim/SimulatedStation.h"

#include <gtest/gtest.h>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2 {
// Failed comparisons show frames as the protocol document writes them.
inline void PrintTo(const CanFrame& frame, std::ostream* out) {
    *out << formatDocument(frame);
}
} // namespace stellwerk::cs2

namespace stellwerk::sim::test {

using can::CanFrame;

// The UID of the document's examples ("CS2 mit SNr. 08").
inline constexpr std::uint32_t DocumentUid = 0x43533208;
inline constexpr std::uint32_t UnboundMfxUid = 0xFFFA8C43; // the document's bind example
inline constexpr std::uint32_t BoundMfxUid = 0x7F001234;   // bound to SID 5 in lokomotive.cs2

inline const char* const locomotives = R"([lokomotive]
version
 .minor=3
session
 .id=2
lokomotive
 .uid=0xc003
 .name=BR 218
 .adresse=0x3
 .typ=dcc
 .mfxuid=0x0
 .vmax=200
 .velocity=0
 .richtung=0
lokomotive
 .uid=0x4005
 .name=ICE 3
 .adresse=0x5
 .typ=mfx
 .sid=0x5
 .mfxuid=0x7f001234
lokomotive
 .uid=0x4006
 .name=Taurus
 .adresse=0x6
 .typ=mfx
 .sid=0x0
 .mfxuid=0xfffa8c43
lokomotive
 .uid=0x48
 .name=V 200
 .adresse=0x48
 .typ=mm2_prg
)";

inline const char* const accessories = R"([magnetartikel]
version
 .minor=1
artikel
 .id=1
 .name=W1
 .typ=rechtsweiche
 .stellung=1
 .dectyp=mm2
artikel
 .id=5
 .name=S5
 .typ=lichtsignal_HP01
 .stellung=0
 .dectyp=dcc
)";

inline const char* const trackPlan = R"([gleisbild]
version
 .major=1
groesse
zuletztBenutzt
 .name=Bahnhof
seite
 .name=Bahnhof
seite
 .id=1
 .name=Depot
)";

inline const char* const stationPage = R"([gleisbildseite]
version
 .major=1
element
 .id=0x102
 .typ=gerade
 .drehung=1
element
 .id=0x103
 .typ=rechtsweiche
 .artikel=2
)";

inline StationLayout inlineLayout() {
    return StationLayout::fromFiles({{"lokomotive.cs2", locomotives},
                                     {"magnetartikel.cs2", accessories},
                                     {"gleisbild.cs2", trackPlan},
                                     {"gleisbilder/Bahnhof.cs2", stationPage}});
}

inline CanFrame frame(std::string_view documentLine) {
    auto parsed = can::parseFrame(documentLine);
    EXPECT_TRUE(parsed.hasValue()) << documentLine;
    return parsed ? parsed->frame : CanFrame{};
}

// A simulated station with the document's UID, and everything it sent.
class StationProbe {
public:
    explicit StationProbe(SimulatedStation::Options options = defaultOptions(),
                          StationLayout layout = inlineLayout())
        : station(std::move(layout), options) {
        QObject::connect(&station, &SimulatedStation::framesEmitted, &station,
                         [this](const std::vector<CanFrame>& frames) { batches.push_back(frames); });
    }

    static SimulatedStation::Options defaultOptions() {
        SimulatedStation::Options options;
        options.uid = DocumentUid;
        return options;
    }

    // Sends one frame; returns what the station answered (one emission, or nothing).
    std::vector<CanFrame> send(const CanFrame& request) {
        const std::size_t before = batches.size();
        station.receive(request);
        EXPECT_LE(batches.size(), before + 1) << "one answer is one emission";
        return batches.size() > before ? batches.back() : std::vector<CanFrame>{};
    }
    std::vector<CanFrame> send(std::string_view documentLine) { return send(frame(documentLine)); }

    // A document frame as the station's answer: the response bit and the station's hash.
    CanFrame answer(std::string_view documentLine) const {
        CanFrame result = frame(documentLine);
        result.id = cs2::makeId(cs2::prio(result), cs2::command(result), true, station.hash());
        return result;
    }

    cs2::Message decoded(const CanFrame& f) const {
        auto message = cs2::decode(f);
        EXPECT_TRUE(message.hasValue()) << can::formatDocument(f);
        return message ? *message : cs2::Message{};
    }

    SimulatedStation station;
    std::vector<std::vector<CanFrame>> batches;
};

} // namespace stellwerk::sim::test
