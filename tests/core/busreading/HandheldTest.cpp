// The monitor's handheld filter: a handheld as people type it, matched against what a frame names.

#include "busreading/Handheld.h"

#include <gtest/gtest.h>

namespace stellwerk::busreading::test {

TEST(HandheldReference, EitherNodeOfThePairNamesTheHandheld) {
    const Handheld ms1{43, "KS MS1"};
    ASSERT_TRUE(HandheldReference::parse("43"));
    EXPECT_TRUE(HandheldReference::parse("43")->matches(ms1));
    EXPECT_TRUE(HandheldReference::parse(" 42 ")->matches(ms1)) << "its master's node";
    EXPECT_FALSE(HandheldReference::parse("44")->matches(ms1));
    EXPECT_FALSE(HandheldReference::parse("41")->matches(ms1));
    EXPECT_TRUE(HandheldReference::parse("0")->matches(Handheld{1, {}})) << "the MS1-master's pair 0/1";
}

TEST(HandheldReference, ANameMatchesInAnyCase) {
    const Handheld ms1{43, "KS MS1"};
    EXPECT_TRUE(HandheldReference::parse("ks ms1")->matches(ms1));
    EXPECT_TRUE(HandheldReference::parse("  KS MS1 ")->matches(ms1));
    EXPECT_FALSE(HandheldReference::parse("KS")->matches(ms1)) << "the whole name";
    EXPECT_FALSE(HandheldReference::parse("KS MS1")->matches(Handheld{43, {}})) << "a name not yet sent";
}

TEST(HandheldReference, RefusesWhatIsNoHandheld) {
    EXPECT_FALSE(HandheldReference::parse(""));
    EXPECT_FALSE(HandheldReference::parse("   "));
    EXPECT_FALSE(HandheldReference::parse("126")) << "the login node";
    EXPECT_FALSE(HandheldReference::parse("127")) << "the flash node";
    EXPECT_FALSE(HandheldReference::parse("99999999999999999999"));
}

} // namespace stellwerk::busreading::test
