// Chapter 7: config data requests answered with the acknowledgement and the CS2's stream framing.

#include "SimTestSupport.h"
#include "cs2config/AccessoryStatusFile.h"
#include "cs2config/ConfigStreamReceiver.h"
#include "cs2config/ConfigStreamRequest.h"
#include "cs2config/LocomotiveStateFile.h"
#include "cs2config/Ms2LocoInfo.h"
#include "cs2config/Ms2LocoNames.h"

namespace stellwerk::sim::test {
namespace {

using Frames = std::vector<CanFrame>;
constexpr std::uint16_t RequesterHash = 0x4711;

// Sends a request's frames; returns everything the station answered.
Frames request(StationProbe& probe, const cs2config::ConfigRequest& request) {
    Frames answers;
    for (const CanFrame& f : request.frames(RequesterHash)) {
        const Frames part = probe.send(f);
        answers.insert(answers.end(), part.begin(), part.end());
    }
    return answers;
}

// The file the stream in `answers` carries, reassembled as a client does.
std::optional<std::string> received(const Frames& answers, const std::string& key) {
    cs2config::ConfigStreamReceiver receiver;
    receiver.expectFile(key, RequesterHash);
    for (const CanFrame& f : answers)
        for (auto& outcome : receiver.feed(f))
            if (outcome)
                return outcome->contents;
    return std::nullopt;
}

cs2config::ConfigRequest keyRequest(std::string_view key, std::string_view qualifier = {}) {
    return *cs2config::ConfigRequest::forKey(key, qualifier);
}

TEST(ConfigData, LoksIsAcknowledgedAndStreamedAsTheServedFile) {
    StationProbe probe;
    const Frames answers = request(probe, keyRequest("loks"));
    ASSERT_GE(answers.size(), 3u);
    const Frames ack = keyRequest("loks").frames(RequesterHash, true);
    EXPECT_EQ(answers[0], ack[0]) << "the request with the response bit";
    EXPECT_EQ(cs2::command(answers[1]), 0x21);
    EXPECT_EQ(answers[1].dlc, 6) << "header of a stream to one requester";
    EXPECT_EQ(cs2::hash(answers[1]), RequesterHash) << "streams carry the requester's hash (7.2)";
    EXPECT_EQ(received(answers, "loks"), std::string(locomotives));
}

TEST(ConfigData, EveryLayoutKeyServesItsFile) {
    StationProbe probe;
    EXPECT_EQ(received(request(probe, keyRequest("mags")), "mags"), std::string(accessories));
    EXPECT_EQ(received(request(probe, keyRequest("gbs")), "gbs"), std::string(trackPlan));
    EXPECT_EQ(received(request(probe, keyRequest("gbs-0")), "gbs-0"), std::string(stationPage));
}

TEST(ConfigData, KeysWithoutAFileAreAcknowledgedWithoutStream) {
    StationProbe probe;
    EXPECT_EQ(request(probe, keyRequest("fs")), keyRequest("fs").frames(RequesterHash, true));
    EXPECT_EQ(request(probe, keyRequest("gbs-1")), keyRequest("gbs-1").frames(RequesterHash, true))
        << "page 1 has no file";
    EXPECT_EQ(request(probe, keyRequest("xyz")), keyRequest("xyz").frames(RequesterHash, true));
}

TEST(ConfigData, LoknamenListsTheRequestedLocomotives) {
    StationProbe probe;
    const auto text = received(request(probe, *cs2config::ConfigRequest::locoNames(1, 2)), "loknamen");
    ASSERT_TRUE(text);
    cs2config::Diagnostics diagnostics;
    const auto names =
        cs2config::Ms2LocoNames::read(cs2config::Document::parse(*text, diagnostics), diagnostics);
    ASSERT_EQ(names.entries.size(), 2u);
    EXPECT_EQ(names.entries[0].name, "ICE 3");
    EXPECT_EQ(names.entries[1].number, 2);
    EXPECT_EQ(names.total, 4);
}

TEST(ConfigData, LokinfoCarriesTheNamedLocomotive) {
    StationProbe probe;
    const auto text = received(request(probe, cs2config::ConfigRequest::locoInfo("Taurus")), "lokinfo");
    ASSERT_TRUE(text);
    cs2config::Diagnostics diagnostics;
    const auto info =
        cs2config::Ms2LocoInfo::read(cs2config::Document::parse(*text, diagnostics), diagnostics);
    ASSERT_TRUE(info.locomotive);
    EXPECT_EQ(info.locomotive->mfxUid, UnboundMfxUid);
}

TEST(ConfigData, LokstatAndMagstatFollowTheState) {
    StationProbe probe;
    probe.send("00084711 6 00 00 C0 03 01 F4");
    probe.send("00164711 6 00 00 38 04 01 01");
    cs2config::Diagnostics diagnostics;
    const auto lokstat = received(request(probe, keyRequest("lokstat")), "lokstat");
    ASSERT_TRUE(lokstat);
    const auto locos =
        cs2config::LocomotiveStateFile::read(cs2config::Document::parse(*lokstat, diagnostics), diagnostics);
    ASSERT_NE(locos.find("BR 218"), nullptr);
    EXPECT_EQ(locos.find("BR 218")->velocity, 500);

    const auto magstat = received(request(probe, keyRequest("magstat")), "magstat");
    ASSERT_TRUE(magstat);
    const auto states =
        cs2config::AccessoryStatusFile::read(cs2config::Document::parse(*magstat, diagnostics), diagnostics);
    ASSERT_NE(states.find(5), nullptr);
    EXPECT_EQ(states.find(5)->position, 1);
}

} // namespace
} // namespace stellwerk::sim::test
