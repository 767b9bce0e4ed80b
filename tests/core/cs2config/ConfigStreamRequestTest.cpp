// Config data requests (command 0x20, document 7.1): the frames a requester sends, and recognising
// them (with their follow-up frames) on the bus.

#include "cs2config/ConfigStreamRequest.h"

#include "ConfigStreamTestSupport.h"
#include "cs2config/ConfigStreamKeys.h"
#include "cs2config/ConfigStreamRequestCollector.h"

#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::cs2config;
using test::frame;

namespace {

std::vector<std::string> documentLines(const std::vector<can::CanFrame>& frames) {
    std::vector<std::string> lines;
    for (const auto& f : frames)
        lines.push_back(can::formatDocument(f));
    return lines;
}

std::vector<CollectedConfigRequest> collect(ConfigRequestCollector& collector,
                                            const std::vector<can::CanFrame>& frames) {
    std::vector<CollectedConfigRequest> found;
    for (const auto& f : frames) {
        const auto message = cs2::decode(f);
        EXPECT_TRUE(message.hasValue()) << can::formatDocument(f);
        if (!message)
            continue;
        if (auto request = collector.feed(*message))
            found.push_back(*request);
    }
    return found;
}

std::vector<can::CanFrame> concat(std::vector<can::CanFrame> a, const std::vector<can::CanFrame>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

} // namespace

// ---- Building requests --------------------------------------------------------------------------

TEST(ConfigRequest, LoksIsOneFrameWithTheKeyZeroPadded) {
    const auto request = ConfigRequest::forKey("loks");
    ASSERT_TRUE(request.hasValue());
    EXPECT_EQ(documentLines(request->frames(0x4711)),
              std::vector<std::string>{"00404711 8 6C 6F 6B 73 00 00 00 00"});
}

TEST(ConfigRequest, EveryKeyWithoutFollowUpIsOneFrame) {
    for (const char* key : {"mags", "fs", "gbs", "gbs-3", "lokstat", "loksstat", "magstat", "gbsstat",
                            "ldbver", "lokdb", "lang", "langver", "lokliste"}) {
        SCOPED_TRACE(key);
        const auto request = ConfigRequest::forKey(key);
        ASSERT_TRUE(request.hasValue());
        const auto frames = request->frames(0x4711);
        ASSERT_EQ(frames.size(), 1u);
        const auto body = cs2::test::decodeAs<cs2::ConfigDataRequest>(can::formatDocument(frames[0]));
        EXPECT_EQ(body.text(), key);
    }
}

TEST(ConfigRequest, EightCharacterKeyFillsTheFrameWithoutTerminator) {
    const auto request = ConfigRequest::forKey("loknamen", "0 2");
    ASSERT_TRUE(request.hasValue());
    EXPECT_EQ(documentLines(request->frames(0x4711)),
              (std::vector<std::string>{"00404711 8 6C 6F 6B 6E 61 6D 65 6E",
                                        "00404711 8 30 20 32 00 00 00 00 00"}));
}

TEST(ConfigRequest, LokinfoCarriesTheLocoNameInTwoFrames) {
    const auto frames = ConfigRequest::locoInfo("BR 218 Intercity").frames(0x4711);
    EXPECT_EQ(documentLines(frames), (std::vector<std::string>{"00404711 8 6C 6F 6B 69 6E 66 6F 00",
                                                               "00404711 8 42 52 20 32 31 38 20 49",
                                                               "00404711 8 6E 74 65 72 63 69 74 79"}));
}

TEST(ConfigRequest, LokinfoWithAShortNameSendsAZeroSecondFrame) {
    const auto frames = ConfigRequest::locoInfo("M4").frames(0x4711);
    EXPECT_EQ(documentLines(frames), (std::vector<std::string>{"00404711 8 6C 6F 6B 69 6E 66 6F 00",
                                                               "00404711 8 4D 34 00 00 00 00 00 00",
                                                               "00404711 8 00 00 00 00 00 00 00 00"}));
}

TEST(ConfigRequest, LokinfoTakesTheBeginningOfALongName) {
    EXPECT_EQ(ConfigRequest::locoInfo("ABCDEFGHIJKLMNOPQRSTUVWXYZ").qualifier(), "ABCDEFGHIJKLMNOP");
    // "Ä" (C3 84) would straddle byte 16: it is left out rather than cut in half.
    EXPECT_EQ(ConfigRequest::locoInfo("ABCDEFGHIJKLMNO\xC3\x84X").qualifier(), "ABCDEFGHIJKLMNO");
}

TEST(ConfigRequest, LoknamenAndMaginfoCarryFirstAndCount) {
    const auto names = ConfigRequest::locoNames(3, 2);
    ASSERT_TRUE(names.hasValue());
    EXPECT_EQ(names->key(), "loknamen");
    EXPECT_EQ(names->qualifier(), "3 2");
    EXPECT_EQ(names->range(), (RequestRange{3, 2}));

    const auto accessories = ConfigRequest::accessoryInfo(12, 40);
    ASSERT_TRUE(accessories.hasValue());
    EXPECT_EQ(documentLines(accessories->frames(0x4711)),
              (std::vector<std::string>{"00404711 8 6D 61 67 69 6E 66 6F 00",
                                        "00404711 8 31 32 20 34 30 00 00 00"}));
}

TEST(ConfigRequest, TheAcknowledgementIsTheSameFrameWithTheResponseBit) {
    const auto frames = ConfigRequest::forKey("gbs-2")->frames(0x4711, true);
    EXPECT_EQ(documentLines(frames), std::vector<std::string>{"00414711 8 67 62 73 2D 32 00 00 00"});
}

TEST(ConfigRequest, RangeThatDoesNotFitIsRefused) {
    const auto request = ConfigRequest::locoNames(1000000, 1000);
    ASSERT_FALSE(request.hasValue());
    EXPECT_EQ(request.error(),
              "config key 'loknamen': '1000000 1000' has 12 bytes, the follow-up frames hold 8");
}

TEST(ConfigRequest, KeysMustHaveOneToEightBytes) {
    EXPECT_EQ(ConfigRequest::forKey("").error(), "config key '' must have 1 to 8 bytes");
    EXPECT_EQ(ConfigRequest::forKey("lokomotive").error(), "config key 'lokomotive' must have 1 to 8 bytes");
    EXPECT_TRUE(ConfigRequest::forKey("blokinfo").hasValue());
}

TEST(ConfigRequest, NulBytesAreRefused) {
    EXPECT_FALSE(ConfigRequest::forKey(std::string_view("lo\0ks", 5)).hasValue());
    EXPECT_FALSE(ConfigRequest::forKey("lokinfo", std::string_view("a\0b", 3)).hasValue());
}

TEST(ConfigRequest, KeysWithoutFollowUpTakeNoQualifier) {
    EXPECT_EQ(ConfigRequest::forKey("loks", "1 2").error(), "config key 'loks' takes no follow-up frame");
    EXPECT_EQ(ConfigRequest::forKey("unknown", "x").error(), "config key 'unknown' takes no follow-up frame");
}

TEST(ConfigRequest, RangeIsOnlyReadFromTwoNumbers) {
    EXPECT_FALSE(ConfigRequest::forKey("loknamen", "3")->range().has_value());
    EXPECT_FALSE(ConfigRequest::forKey("loknamen", "a b")->range().has_value());
    EXPECT_FALSE(ConfigRequest::forKey("loknamen", "3 ")->range().has_value());
    EXPECT_EQ(ConfigRequest::forKey("maginfo", "0 10")->range(), (RequestRange{0, 10}));
}

// ---- Recognising requests -----------------------------------------------------------------------

TEST(ConfigRequestCollector, ASingleFrameRequestIsCompleteAtOnce) {
    ConfigRequestCollector collector;
    const auto found = collect(collector, {frame("00404711 8 6C 6F 6B 73 00 00 00 00")});
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].request.key(), "loks");
    EXPECT_EQ(found[0].hash, 0x4711);
    EXPECT_FALSE(found[0].response);
}

TEST(ConfigRequestCollector, LokinfoWaitsForBothNameFrames) {
    ConfigRequestCollector collector;
    const auto frames = ConfigRequest::locoInfo("BR 218 Intercity").frames(0x4711);
    EXPECT_TRUE(collect(collector, {frames[0], frames[1]}).empty());
    EXPECT_EQ(collector.pendingCount(), 1u);
    const auto found = collect(collector, {frames[2]});
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].request, ConfigRequest::locoInfo("BR 218 Intercity"));
    EXPECT_EQ(collector.pendingCount(), 0u);
}

TEST(ConfigRequestCollector, RequestAndAcknowledgementInterleaveFrameByFrame) {
    // Requester sends the key, the station acks it, then the same for the follow-up frame.
    const auto request = ConfigRequest::locoNames(0, 2).value();
    const auto asked = request.frames(0x4711), acked = request.frames(0x4711, true);
    ConfigRequestCollector collector;
    const auto found = collect(collector, {asked[0], acked[0], asked[1], acked[1]});
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].request, request);
    EXPECT_FALSE(found[0].response);
    EXPECT_EQ(found[1].request, request);
    EXPECT_TRUE(found[1].response);
}

TEST(ConfigRequestCollector, TwoRequestersAreKeptApartByHash) {
    const auto a = ConfigRequest::locoInfo("Anna").frames(0x0301);
    const auto b = ConfigRequest::accessoryInfo(1, 5)->frames(0x0302);
    ConfigRequestCollector collector;
    const auto found = collect(collector, {a[0], b[0], a[1], b[1], a[2]});
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].hash, 0x0302);
    EXPECT_EQ(found[0].request.range(), (RequestRange{1, 5}));
    EXPECT_EQ(found[1].hash, 0x0301);
    EXPECT_EQ(found[1].request.qualifier(), "Anna");
}

TEST(ConfigRequestCollector, OtherMessagesAndEmptyKeysAreIgnored) {
    ConfigRequestCollector collector;
    EXPECT_TRUE(
        collect(collector, {frame("00004711 5 00 00 00 00 01"), frame("00404711 8 00 00 00 00 00 00 00 00"),
                            frame("00420300 8 00 00 00 AA 78 9C 8B 4E")})
            .empty());
    EXPECT_EQ(collector.pendingCount(), 0u);
}

TEST(ConfigRequestCollector, EveryTableKeyRoundTrips) {
    ConfigRequestCollector collector;
    for (const auto& row : configFileKeys()) {
        if (row.key == "gbs-#")
            continue;
        const std::string qualifier = row.followUp == FollowUp::LocoName ? "ICE 3 Triebkopf1"
                                      : row.followUp == FollowUp::Range  ? "10 20"
                                                                         : "";
        const auto request = ConfigRequest::forKey(row.key, qualifier);
        ASSERT_TRUE(request.hasValue()) << row.key;
        const auto found = collect(collector, concat(request->frames(0x4711), request->frames(0x4711, true)));
        ASSERT_EQ(found.size(), 2u) << row.key;
        EXPECT_EQ(found[0].request, *request);
        EXPECT_EQ(found[1].request, *request);
    }
}

TEST(ConfigRequestCollector, ResetForgetsARequestWhoseFollowUpWasLost) {
    ConfigRequestCollector collector;
    const auto names = ConfigRequest::locoNames(0, 2)->frames(0x4711);
    EXPECT_TRUE(collect(collector, {names[0]}).empty());
    collector.reset();
    const auto found = collect(collector, ConfigRequest::forKey("loks")->frames(0x4711));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].request.key(), "loks");
}
