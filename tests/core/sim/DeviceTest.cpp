// Chapter 6 (ping, status data configuration) and the readings of system status (2.12, 2.11).

#include "SimTestSupport.h"
#include "cs2/Hash.h"
#include "sim/StatusChannels.h"

#include <charconv>

namespace stellwerk::sim::test {
namespace {

using Frames = std::vector<CanFrame>;

// Reads the strings and numbers of a reassembled status data index.
class IndexReader {
public:
    explicit IndexReader(std::vector<std::uint8_t> bytes) : bytes_(std::move(bytes)) {}
    std::uint8_t u8() { return at_ < bytes_.size() ? bytes_[at_++] : 0; }
    std::uint16_t u16() { return std::uint16_t(u8() << 8 | u8()); }
    std::uint32_t u32() { return std::uint32_t(u16()) << 16 | u16(); }
    std::string text() {
        std::string s;
        while (at_ < bytes_.size() && bytes_[at_] != 0)
            s += char(bytes_[at_++]);
        ++at_;
        return s;
    }
    std::string fixed(std::size_t n) {
        std::string s;
        for (std::size_t i = 0; i < n; ++i)
            if (const char c = char(u8()))
                s += c;
        return s;
    }

private:
    std::vector<std::uint8_t> bytes_;
    std::size_t at_ = 0;
};

double number(const std::string& label) {
    double value = 0;
    std::from_chars(label.data(), label.data() + label.size(), value);
    return value;
}

// Sends a 0x1D request and reassembles the packets as a client does: checks their hashes and the
// end frame's count.
std::vector<std::uint8_t> statusIndex(StationProbe& probe, std::uint32_t uid, std::uint8_t index) {
    cs2::StatusDataConfig request;
    request.device = uid;
    request.index = index;
    const Frames frames = probe.send(cs2::encode(cs2::Message{0, false, 0x4711, request}));
    std::vector<std::uint8_t> bytes;
    EXPECT_FALSE(frames.empty());
    for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
        const auto body = std::get<cs2::StatusDataConfig>(probe.decoded(frames[i]).body);
        EXPECT_EQ(body.form, cs2::StatusDataConfig::Form::Packet);
        EXPECT_EQ(cs2::hash(frames[i]), 0x0301 + i);
        EXPECT_EQ(frames[i].dlc, 8);
        bytes.insert(bytes.end(), body.packet.view().begin(), body.packet.view().end());
    }
    const CanFrame& last = frames.back();
    const auto end = std::get<cs2::StatusDataConfig>(probe.decoded(last).body);
    EXPECT_EQ(end.form, cs2::StatusDataConfig::Form::End);
    EXPECT_EQ(cs2::hash(last), probe.station.hash());
    EXPECT_EQ(end.packetCount, frames.size() - 1);
    EXPECT_EQ(end.index, index);
    return bytes;
}

std::uint16_t readChannel(StationProbe& probe, std::uint8_t channel) {
    cs2::SystemStatus read{DocumentUid, channel, std::nullopt, std::nullopt};
    const Frames answer = probe.send(cs2::encode(cs2::Message{0, false, 0x4711, read}));
    EXPECT_EQ(answer.size(), 1u);
    return answer.empty() ? 0 : std::get<cs2::SystemStatus>(probe.decoded(answer[0]).body).value.value_or(0);
}

TEST(Ping, AnsweredAsCs2MasterAndAsGleisbox) {
    auto options = StationProbe::defaultOptions();
    options.gleisbox = true;
    StationProbe probe(options);
    const Frames answers = probe.send("00304711 0");
    ASSERT_EQ(answers.size(), 2u);
    EXPECT_EQ(answers[0], probe.answer("00304711 8 43 53 32 08 04 02 FF FF"));
    EXPECT_EQ(answers[1], probe.answer("00304711 8 47 43 10 01 01 27 00 10"));
}

TEST(StatusDataConfig, DeviceDescriptionIndexZero) {
    StationProbe probe;
    IndexReader index(statusIndex(probe, DocumentUid, 0));
    EXPECT_EQ(index.u8(), 4) << "readings";
    EXPECT_EQ(index.u8(), 2) << "config channels";
    index.u16();
    EXPECT_EQ(index.u32(), DocumentUid);
    EXPECT_EQ(index.fixed(8), "60215");
    EXPECT_EQ(index.text(), "Central Station 2");
}

TEST(StatusDataConfig, ReadingChannelsDescribeCurrentVoltageAndTemperature) {
    StationProbe probe;
    const std::vector<std::string> names{"HGL", "PGL", "VOLT", "TEMP"};
    for (std::uint8_t i = 1; i <= 4; ++i) {
        IndexReader index(statusIndex(probe, DocumentUid, i));
        EXPECT_EQ(index.u8(), i) << "query channel";
        index.u8();
        for (int c = 0; c < 4; ++c)
            index.u8();
        index.u16();
        for (int e = 0; e < 4; ++e)
            index.u16();
        EXPECT_EQ(index.text(), names[i - 1u]);
    }
}

TEST(StatusDataConfig, ListAndSliderConfigChannels) {
    StationProbe probe;
    IndexReader list(statusIndex(probe, DocumentUid, 5));
    EXPECT_EQ(list.u8(), 5);
    EXPECT_EQ(list.u8(), 1) << "list";
    EXPECT_EQ(list.u8(), 3) << "options";
    EXPECT_EQ(list.u8(), 2) << "current";
    list.u32();
    EXPECT_EQ(list.text(), "Betrieb mit Stromversorgung");
    EXPECT_EQ(list.text(), "Trafo 60 VA 60052");

    IndexReader slider(statusIndex(probe, DocumentUid, 6));
    EXPECT_EQ(slider.u8(), 6);
    EXPECT_EQ(slider.u8(), 2) << "number";
    EXPECT_EQ(slider.u16(), 500);
    EXPECT_EQ(slider.u16(), 4500);
    EXPECT_EQ(slider.u16(), 4000);
    EXPECT_EQ(slider.text(), "Variable Strombegrenzung");
}

TEST(StatusDataConfig, UnknownIndexEndsWithoutPacketsAndOtherDevicesAreSilent) {
    StationProbe probe;
    EXPECT_TRUE(statusIndex(probe, DocumentUid, 9).empty());
    cs2::StatusDataConfig request;
    request.device = 0x12345678;
    EXPECT_TRUE(probe.send(cs2::encode(cs2::Message{0, false, 0x4711, request})).empty());
}

TEST(StatusDataConfig, GleisboxDescribesTheRealFigures) {
    auto options = StationProbe::defaultOptions();
    options.gleisbox = true;
    StationProbe probe(options);
    IndexReader track(statusIndex(probe, options.gleisboxUid, 1));
    EXPECT_EQ(track.u8(), 1);
    EXPECT_EQ(std::int8_t(track.u8()), -3);
    for (int c = 0; c < 4; ++c)
        track.u8();
    EXPECT_EQ(track.u16(), 0x000F);
    track.u16(), track.u16(), track.u16();
    EXPECT_EQ(track.u16(), 0x080C);
    EXPECT_EQ(track.text(), "TRACK");
}

TEST(SystemStatus, DocumentExampleReadsTheMainTrackCurrent) {
    StationProbe probe;
    probe.send("00004711 5 00 00 00 00 01");
    probe.station.setTrackLoad(3);
    EXPECT_EQ(probe.send("00004711 6 43 53 32 08 0B 01"),
              Frames{probe.answer("00014711 8 43 53 32 08 0B 01 00 03")});
}

TEST(SystemStatus, ReadingsFollowTheLoadAndDisplayAsDescribed) {
    StationProbe probe;
    probe.send("00004711 5 00 00 00 00 01");
    probe.station.setTrackLoad(1200);
    IndexReader description(statusIndex(probe, DocumentUid, 1));
    description.u8(), description.u8(), description.u32();
    const std::uint16_t zero = description.u16();
    description.u16(), description.u16(), description.u16();
    const std::uint16_t end4 = description.u16();
    description.text();
    const double start = number(description.text()), end = number(description.text());
    const std::uint16_t raw = readChannel(probe, 1);
    EXPECT_NEAR(start + (raw - zero) * (end - start) / (end4 - zero), 1.2, 0.001);

    const std::uint16_t voltAtLoad = readChannel(probe, 3), warmAtLoad = readChannel(probe, 4);
    probe.station.setTrackLoad(100);
    EXPECT_GT(readChannel(probe, 3), voltAtLoad) << "less load, less voltage drop";
    EXPECT_LT(readChannel(probe, 4), warmAtLoad);
}

TEST(SystemStatus, UnknownChannelIsConfirmedWithoutValue) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00004711 6 43 53 32 08 0B 0F"),
              Frames{probe.answer("00004711 6 43 53 32 08 0B 0F")});
}

TEST(SystemStatus, ConfigWritesAreAcceptedOrRejected) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00004711 8 43 53 32 08 0B 05 00 01"),
              Frames{probe.answer("00004711 7 43 53 32 08 0B 05 01")});
    EXPECT_EQ(probe.send("00004711 8 43 53 32 08 0B 05 00 07"),
              Frames{probe.answer("00004711 7 43 53 32 08 0B 05 00")});
    EXPECT_EQ(probe.send("00004711 8 43 53 32 08 0B 01 00 07"),
              Frames{probe.answer("00004711 7 43 53 32 08 0B 01 00")});
    EXPECT_EQ(probe.station.statusChannels().setting(5), 1);
}

TEST(Overload, AboveTheLimitTheStationReportsAndStops) {
    StationProbe probe;
    probe.send("00004711 5 00 00 00 00 01");
    probe.station.setTrackLoad(3900);
    EXPECT_EQ(probe.batches.size(), 1u) << "below the 4.000 A limit: nothing";
    probe.station.setTrackLoad(4200);
    ASSERT_EQ(probe.batches.size(), 2u);
    EXPECT_EQ(probe.batches[1], (Frames{probe.answer("00004711 6 43 53 32 08 0A 01"),
                                        probe.answer("00004711 5 43 53 32 08 00")}));
    EXPECT_EQ(probe.station.power(), SimulatedStation::Power::Stopped);
    EXPECT_EQ(readChannel(probe, 1), 0) << "no current on a switched-off track";
}

TEST(Overload, LoweringTheLimitBelowTheLoadTripsIt) {
    StationProbe probe;
    probe.send("00004711 5 00 00 00 00 01");
    probe.station.setTrackLoad(2000);
    const Frames answer = probe.send("00004711 8 43 53 32 08 0B 06 05 DC"); // 1.500 A
    ASSERT_EQ(answer.size(), 3u);
    EXPECT_EQ(answer[0], probe.answer("00004711 7 43 53 32 08 0B 06 01"));
    EXPECT_EQ(answer[1], probe.answer("00004711 6 43 53 32 08 0A 01"));
}

} // namespace
} // namespace stellwerk::sim::test
