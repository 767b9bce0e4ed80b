// Chapter 3.1-3.3: mfx discovery, bind and verify against the layout's mfx decoders.

#include "SimTestSupport.h"

namespace stellwerk::sim::test {
namespace {

using Frames = std::vector<CanFrame>;

TEST(MfxRegistration, FullDiscoveryFindsTheUnboundDecoder) {
    StationProbe probe;
    const Frames answers = probe.send("00024711 1 20");
    ASSERT_EQ(answers.size(), 33u);
    // The steps of the search (form 3, DLC 5): the UID bits known so far and the range.
    EXPECT_EQ(answers[0], probe.answer("00024711 5 80 00 00 00 01"));
    EXPECT_EQ(answers[15], probe.answer("00024711 5 FF FA 00 00 10"));
    EXPECT_EQ(answers[30], probe.answer("00024711 5 FF FA 8C 42 1F"));
    // The last step comes with and without the ASK ratio.
    EXPECT_EQ(answers[31], probe.answer("00024711 6 FF FA 8C 43 20 D1"));
    EXPECT_EQ(answers[32], probe.answer("00024711 5 FF FA 8C 43 20"));
}

TEST(MfxRegistration, ANewDecoderOnTheTrackIsFoundAfterTheLayoutsOwn) {
    SimulatedStation::Options options = StationProbe::defaultOptions();
    options.newMfxDecoders = {0x7A3C1E10};
    StationProbe probe(options);
    probe.send("00044711 6 FF FA 8C 43 00 07"); // the layout's unbound decoder is registered
    const Frames answers = probe.send("00024711 1 20");
    ASSERT_FALSE(answers.empty());
    EXPECT_EQ(answers.back(), probe.answer("00024711 5 7A 3C 1E 10 20"));
}

TEST(MfxRegistration, DiscoverBindVerifyThenDriveOnTheNewSid) {
    StationProbe probe;
    probe.send("00024711 1 20");
    EXPECT_EQ(probe.send("00044711 6 FF FA 8C 43 00 07"),
              Frames{probe.answer("00044711 6 FF FA 8C 43 00 07")});
    EXPECT_EQ(probe.send("00064711 6 FF FA 8C 43 00 07"),
              Frames{probe.answer("00064711 7 FF FA 8C 43 00 07 D1")});
    EXPECT_EQ(probe.send("00084711 6 00 00 40 07 01 F4"),
              Frames{probe.answer("00084711 6 00 00 40 07 01 F4")});
    EXPECT_EQ(probe.station.loco(0x4007)->speed, 500);
    // Every decoder is bound now: a new discovery finds nothing.
    EXPECT_EQ(probe.send("00024711 1 20"), Frames{probe.answer("00024711 0")});
}

TEST(MfxRegistration, BindExampleIsConfirmed) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00044711 6 FF FA 8C 43 00 05"),
              Frames{probe.answer("00044711 6 FF FA 8C 43 00 05")});
    // SID 5 belonged to another decoder, which lost it.
    EXPECT_EQ(probe.send("00064711 6 7F 00 12 34 00 05"),
              Frames{probe.answer("00064711 6 7F 00 12 34 00 00")});
}

TEST(MfxRegistration, VerifyExamplesPositiveAndNegative) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00064711 6 FF FA 8C 43 00 05"),
              Frames{probe.answer("00064711 6 FF FA 8C 43 00 00")});
    EXPECT_EQ(probe.send("00064711 6 7F 00 12 34 00 05"),
              Frames{probe.answer("00064711 7 7F 00 12 34 00 05 D1")});
}

TEST(MfxRegistration, SingleRangeStepAnswersWhenADecoderMatches) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00024711 5 FF 00 00 00 08"), Frames{probe.answer("00024711 6 FF 00 00 00 08 D1")});
    EXPECT_TRUE(probe.send("00024711 5 00 00 00 00 08").empty());
}

TEST(MfxRegistration, Mm2DiscoveryFindsNothing) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00024711 1 21"), Frames{probe.answer("00024711 0")});
}

} // namespace
} // namespace stellwerk::sim::test
