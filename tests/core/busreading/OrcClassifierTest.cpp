// The classifier on a bus shared by the CS2, OpenRailCAN devices and MS1 handhelds (ORC notes A7, C4, O26):
// the 33 example frames of the CS2 document (seed 003) stay the CS2's, the notes' derived ORC vectors (A4.2)
// are ORC, and where M-CAN is expected, the notes' decision holds: ORC claims nothing (or only ids with the
// CS2 marker, when the profile allows it) and no M-CAN frame is ever taken for ORC.

#include "../mcan/SeedTrace.h"
#include "busreading/FrameClassifier.h"
#include "busreading/FrameDescription.h"
#include "can/FrameText.h"

#include <gtest/gtest.h>

namespace stellwerk::busreading::test {
namespace {

using can::CanFrame;

// Every frame printed in the CS2 document (seed 003) as "ID DLC bytes", with its comment cut off.
std::vector<CanFrame> cs2DocumentFrames() {
    std::ifstream in(seeds::seedPath("003_e81750172fa08e9b.txt"));
    const std::regex row(R"(([0-9A-Fa-f]{8}) ([0-8])((?: [0-9A-Fa-f]{2})+))");
    std::vector<CanFrame> frames;
    for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (!std::regex_search(line, m, row))
            continue;
        CanFrame frame;
        frame.id = std::uint32_t(std::stoul(m[1].str(), nullptr, 16));
        frame.dlc = std::uint8_t(std::stoi(m[2].str()));
        std::istringstream data(m[3].str());
        std::string byte;
        for (std::size_t i = 0; i < frame.dlc && data >> byte; ++i)
            frame.data[i] = std::uint8_t(std::stoul(byte, nullptr, 16));
        frames.push_back(frame);
    }
    return frames;
}

// ORC notes A4.2 V1-V10 (Derived: not in the document).
const char* const DerivedOrcVectors[] = {
    "09000000 1 00",
    "09000000 3 01 2E 01",
    "09000042 3 0A 01 02",
    "09020000 1 00",
    "11100000 4 03 30 05 01",
    "11020000 3 01 00 48",
    "11030000 5 01 00 48 01 F4",
    "17122E01 4 10 2E 01 05",
    "19200000 5 00 3A 2E 2E 01",
    "1D212E01 7 00 3A 2E 2E 01 01 02",
};

CanFrame frame(std::string_view text) {
    return can::parseFrame(text)->frame;
}

BusProfile orcBesideMcan() {
    return BusProfile{Protocol::Mcan, Protocol::Orc, Protocol::Cs2};
}

} // namespace

TEST(OrcClassifier, TheCs2DocumentHas33ExampleFramesAndAllStayCs2) {
    const std::vector<CanFrame> frames = cs2DocumentFrames();
    ASSERT_EQ(frames.size(), 33u);
    for (const BusProfile& profile :
         {BusProfile::openRailCan(), orcBesideMcan(), BusProfile::centralStation()})
        for (const CanFrame& f : frames)
            EXPECT_EQ(classify(f, profile), Protocol::Cs2) << can::formatDocument(f);
}

TEST(OrcClassifier, DerivedA42VectorsAreOrcBesideTheCs2) {
    for (const char* text : DerivedOrcVectors)
        EXPECT_EQ(classify(frame(text), BusProfile::openRailCan()), Protocol::Orc) << text;
}

TEST(OrcClassifier, DerivedA42VectorsDescribeAsOrc) {
    const FrameDescription d(frame("11100000 4 03 30 05 01"), BusProfile::openRailCan());
    EXPECT_EQ(d.protocolName(), "orc");
    EXPECT_EQ(d.name(), "orc.decoder.switch");
    EXPECT_EQ(d.number("target"), std::optional<std::uint64_t>(0x3005));
    EXPECT_EQ(d.json().rfind("{\"protocol\":\"orc\",", 0), 0u) << d.json();
    EXPECT_TRUE(
        FrameDescription(frame("1D212E01 7 00 3A 2E 2E 01 01 02"), BusProfile::openRailCan()).isResponse());
}

// Notes O26 and C4: M-CAN's priorities overlap ORC's; with M-CAN expected, ORC is off on that bus.
TEST(OrcClassifier, McanOnTheBusTurnsOrcOff) {
    for (const char* text : DerivedOrcVectors)
        EXPECT_EQ(classify(frame(text), orcBesideMcan()), Protocol::Mcan) << text;
}

// Notes C4, optional: the central hands out only bus ids with 110 in bits 9..7 (the CS2 hash marker, which
// M-CAN never uses); ORC then claims those frames and M-CAN the rest.
TEST(OrcClassifier, WithTheCs2MarkerOrcSharesABusWithMcan) {
    BusProfile profile = orcBesideMcan();
    profile.orcOnlyWithCs2Marker(true);
    EXPECT_EQ(classify(frame("11100300 4 03 30 05 01"), profile), Protocol::Orc);
    EXPECT_EQ(classify(frame("11100000 4 03 30 05 01"), profile), Protocol::Mcan);
}

// No M-CAN frame of the MS1 trace (seed 000, chapter 11) is taken for ORC, with or without the marker option.
TEST(OrcClassifier, NoMcanTraceFrameIsTakenForOrc) {
    const std::vector<CanFrame> trace = seeds::chapter11Trace(seeds::McanSeed000);
    ASSERT_FALSE(trace.empty());
    BusProfile marked = orcBesideMcan();
    marked.orcOnlyWithCs2Marker(true);
    for (const CanFrame& f : trace) {
        EXPECT_NE(classify(f, orcBesideMcan()), Protocol::Orc) << can::formatDocument(f);
        EXPECT_NE(classify(f, marked), Protocol::Orc) << can::formatDocument(f);
    }
}

// Notes A7 and B7: ID24 set with priority 00 is the band kept for 29-bit RO modules, never ORC.
TEST(OrcClassifier, PriorityZeroWithId24IsNotOrc) {
    EXPECT_NE(classify(frame("01FE0001 8 13 00 00 35 00 20 00 00"), BusProfile::openRailCan()),
              Protocol::Orc);
    EXPECT_EQ(protocolName(Protocol::Orc), "orc");
}

TEST(OrcClassifier, StandardFramesAreNeverOrc) {
    const std::uint8_t data[] = {0x00};
    EXPECT_EQ(classify(CanFrame::standard(0x123, data), BusProfile::openRailCan()), Protocol::Foreign);
}

TEST(OrcClassifier, OrcMessageNamesJoinTheFilterList) {
    const std::vector<std::string_view> names = messageNames(BusProfile::openRailCan());
    EXPECT_NE(std::find(names.begin(), names.end(), "orc.decoder.switch"), names.end());
    const std::vector<std::string_view> station = messageNames(BusProfile::centralStation());
    EXPECT_EQ(std::find(station.begin(), station.end(), "orc.decoder.switch"), station.end());
}

} // namespace stellwerk::busreading::test
