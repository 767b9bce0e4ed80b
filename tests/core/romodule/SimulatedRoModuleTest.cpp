// The simulated RO module on its own: the document's examples carried out, and the notes' decisions where
// the document is silent (R6 bit access, R10 0xFD data, R13 no wrap, R21 0xFE before the job check).
#include "sim/SimulatedRoModule.h"

#include <gtest/gtest.h>

namespace stellwerk::sim::test {
namespace {

using ro::Request;
using ro::Width;

struct Fixture {
    ro::RoProfile profile = ro::RoProfile::simulator(1);
    SimulatedRoModule module{profile};
    std::vector<ro::Answer> answers;

    Fixture() {
        QObject::connect(&module, &SimulatedRoModule::framesEmitted, &module,
                         [this](const std::vector<can::CanFrame>& frames) {
                             for (const auto& frame : frames) {
                                 EXPECT_EQ(frame.id, profile.ids.answer);
                                 answers.push_back(ro::decodeAnswer(frame.payload()).value());
                             }
                         });
    }
    ro::Answer send(const Request& request) {
        module.receive(profile.requestFrame(request));
        return answers.back();
    }
};

TEST(SimulatedRoModule, Section3_3And3_4AreCarriedOut) {
    Fixture f;
    EXPECT_EQ(f.send(Request{Request::Kind::Write, Width::Byte, 0x0012, 0x34, 0x0F}),
              ro::Answer(ro::OkAnswer{Width::None, 0x34, 0}));
    EXPECT_EQ(f.send(Request{Request::Kind::Write, Width::Word, 0x0000, 0x35, 0x2000}),
              ro::Answer(ro::OkAnswer{Width::None, 0x35, 0}));
    EXPECT_TRUE(f.module.relay(14));
    EXPECT_EQ(f.module.relays(), 0x2000u);
    // Derived (notes B4.4): reading the relay word back.
    EXPECT_EQ(f.send(Request{Request::Kind::Read, Width::Word, 0x0000, 0x36}),
              ro::Answer(ro::OkAnswer{Width::Word, 0x36, 0x2000}));
    EXPECT_EQ(f.module.writes().size(), 2u);
}

TEST(SimulatedRoModule, TheSameJobIdTwiceEarnsDuplicate) {
    Fixture f;
    const Request write{Request::Kind::Write, Width::Word, 0x0000, 0x35, 0x2000};
    f.send(write);
    EXPECT_EQ(f.send(write), ro::Answer(ro::DuplicateJobAnswer{0x35}));
    EXPECT_EQ(f.module.writes().size(), 1u) << "not carried out twice";
    f.module.setDuplicateCarriesData(true);
    const Request read{Request::Kind::Read, Width::Word, 0x0000, 0x36};
    f.send(read);
    EXPECT_EQ(f.send(read), ro::Answer(ro::DuplicateJobAnswer{0x36, 2, 0x2000}));
}

TEST(SimulatedRoModule, InvalidCommandsComeFirstAndDoNotUseTheJobId) {
    Fixture f;
    f.module.rememberJob(0x40);
    f.module.receive(can::CanFrame::extendedFrame(0x01FE0001, std::array<std::uint8_t, 8>{0x30, 0, 0, 0x40}));
    EXPECT_EQ(f.answers.back(), ro::Answer(ro::InvalidCommandAnswer{}));
    EXPECT_EQ(f.send(Request{Request::Kind::Read, Width::Long, 0xFFFE, 0x41}),
              ro::Answer(ro::InvalidCommandAnswer{}))
        << "an access past 0xFFFF";
    EXPECT_EQ(f.module.lastJob(), 0x40);
}

TEST(SimulatedRoModule, BitAccessAddressesABitNumber) {
    Fixture f;
    f.send(Request{Request::Kind::Write, Width::Bit, 13, 1, 1});
    EXPECT_TRUE(f.module.relay(14));
    EXPECT_EQ(f.send(Request{Request::Kind::Read, Width::Bit, 13, 2}),
              ro::Answer(ro::OkAnswer{Width::Bit, 2, 1}));
}

TEST(SimulatedRoModule, ChangeFlagsAreClearedByReading) {
    Fixture f;
    f.module.setInput(1, true);
    f.module.setInput(16, true);
    EXPECT_EQ(f.send(Request{Request::Kind::Read, Width::Long, 0x0020, 1}),
              ro::Answer(ro::OkAnswer{Width::Long, 1, 0x80018001}));
    EXPECT_EQ(f.send(Request{Request::Kind::Read, Width::Long, 0x0020, 2}),
              ro::Answer(ro::OkAnswer{Width::Long, 2, 0x00008001}));
}

TEST(SimulatedRoModule, InjectedFaults) {
    Fixture f;
    f.module.loseRequests(1);
    f.module.receive(f.profile.requestFrame(Request{Request::Kind::Write, Width::Word, 0, 1, 1}));
    EXPECT_TRUE(f.answers.empty());
    EXPECT_FALSE(f.module.relay(1)) << "a lost request is not carried out";
    f.module.loseAnswers(1);
    f.module.receive(f.profile.requestFrame(Request{Request::Kind::Write, Width::Word, 0, 2, 1}));
    EXPECT_TRUE(f.answers.empty());
    EXPECT_TRUE(f.module.relay(1)) << "a lost answer's request is";
    f.module.unplug();
    f.module.receive(f.profile.requestFrame(Request{Request::Kind::Read, Width::Word, 0, 3}));
    EXPECT_TRUE(f.answers.empty());
}

} // namespace
} // namespace stellwerk::sim::test
