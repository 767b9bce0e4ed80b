// Document 6.2 and the field notes: status data configuration of a real Gleisbox 60113, reassembled
// from its packets into a description and reading channels with their scaling.

#include "ScriptedStation.h"
#include "station/DeviceDescription.h"
#include "station/StatusDataPackets.h"

namespace stellwerk::station::test {
namespace {

void append(std::vector<std::uint8_t>& bytes, std::string_view text) {
    bytes.insert(bytes.end(), text.begin(), text.end());
    bytes.push_back(0);
}

void append16(std::vector<std::uint8_t>& bytes, std::uint16_t value) {
    bytes.push_back(std::uint8_t(value >> 8));
    bytes.push_back(std::uint8_t(value));
}

std::vector<std::uint8_t> reading(std::uint8_t channel, std::int8_t power, std::uint16_t zero,
                                  std::array<std::uint16_t, 4> ends,
                                  std::initializer_list<std::string_view> texts) {
    std::vector<std::uint8_t> bytes{channel, std::uint8_t(power), 0x00, 0x31, 0xF2, 0xC3};
    append16(bytes, zero);
    for (auto end : ends)
        append16(bytes, end);
    for (auto text : texts)
        append(bytes, text);
    return bytes;
}

void serveGleisbox(ScriptedStation& station) {
    const std::uint32_t uid = ScriptedStation::Uid;
    std::vector<std::uint8_t> summary{3, 0, 0, 0, 0x00, 0x00, 0x30, 0x39, '6', '0', '1', '1', '3', 0, 0, 0};
    append(summary, "Gleisbox");
    station.statusData[{uid, 0}] = summary;
    station.statusData[{uid, 1}] =
        reading(1, -3, 0x000F, {0x0670, 0x06C2, 0x0767, 0x080C}, {"TRACK", "0.00", "2.50", "A"});
    station.statusData[{uid, 2}] =
        reading(3, -3, 0, {0x039D, 0x04B2, 0x0A1E, 0x0C49}, {"VOLT", "10.00", "27.00", "Volt"});
    station.statusData[{uid, 3}] =
        reading(4, 0, 0, {0x006B, 0x00A4, 0x00CD, 0x00DB}, {"TEMP", "0.0", "80.0", "C"});
}

TEST(StatusData, GleisboxDescriptionIsReassembledIntoReadingChannels) {
    Bench bench;
    serveGleisbox(bench.station);
    std::optional<DeviceDescription> device;
    QStringList problems;
    bench.session.statusData().read({ScriptedStation::Uid, 1, 0x27, 0x0010},
                                    [&](const DeviceDescription& d, const QStringList& p) {
                                        device = d;
                                        problems = p;
                                    });
    ASSERT_TRUE(waitFor([&] { return device.has_value(); }));
    EXPECT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(device->summary);
    EXPECT_EQ(device->summary->article, "60113");
    EXPECT_EQ(device->summary->name, "Gleisbox");
    EXPECT_EQ(device->summary->serial, 12345u);
    EXPECT_EQ(bench.station.count(cs2::Command::StatusDataConfig), 4u) << "index 0 and the three readings";
    ASSERT_EQ(device->readings.size(), 3u);
    const auto& track = device->readings[0];
    EXPECT_EQ(track.channel, 1);
    EXPECT_EQ(track.name, "TRACK");
    EXPECT_EQ(track.unit, "A");
    EXPECT_NEAR(track.scaled(46), 0.038, 0.0005);
    EXPECT_EQ(track.decimals(), 2);
    const auto& volt = device->readings[1];
    EXPECT_EQ(volt.channel, 3) << "the query channel need not equal the index";
    EXPECT_NEAR(volt.scaled(2177), 21.8, 0.05);
    const auto& temp = device->readings[2];
    EXPECT_EQ(temp.channel, 4);
    EXPECT_NEAR(temp.scaled(40), 14.6, 0.05);
}

TEST(StatusData, DocumentsListAndSliderConfigChannels) {
    std::vector<std::uint8_t> list{0x01, 1, 3, 0, 0, 0, 0, 0};
    for (auto text :
         {"Betrieb mit Stromversorgung", "Trafo 60 VA 60052", "Schaltnetzteil 60061", "Schaltnetzteil 60101"})
        append(list, text);
    const auto choice = parseConfigChannel(4, list);
    ASSERT_TRUE(choice);
    EXPECT_EQ(choice->kind, ConfigChannel::Kind::List);
    EXPECT_EQ(choice->title, "Betrieb mit Stromversorgung");
    EXPECT_EQ(choice->options.size(), 3u);

    std::vector<std::uint8_t> slider{0x05, 2};
    append16(slider, 0);
    append16(slider, 660);
    append16(slider, 500);
    for (auto text : {"Variable Strombegrenzung", "0.000", "2.500", "A"})
        append(slider, text);
    const auto number = parseConfigChannel(5, slider);
    ASSERT_TRUE(number);
    EXPECT_EQ(number->kind, ConfigChannel::Kind::Number);
    EXPECT_EQ(number->channel, 5);
    EXPECT_EQ(number->maximum, 660);
    EXPECT_EQ(number->value, 500);
    EXPECT_EQ(number->unit, "A");
}

// Issue 11 (found by fuzzing): the article number was copied raw, so a device on the bus could send
// invalid UTF-8 and terminal escapes to the CLI. It keeps printable ASCII only; the texts lose their
// control characters.
TEST(StatusData, ArticleAndNamesKeepPrintableCharactersOnly) {
    std::vector<std::uint8_t> summary{1, 0, 0, 0, 0, 0, 0, 1, 0x1B, '[', '2', 'J', '6', 0xFF, '0', 0x07};
    append(summary, "Gleis\x1b]0;owned\x07"
                    "box");
    append(summary, "Nick\xc2\x9b"
                    "1m");
    const auto device = parseDeviceSummary(summary);
    ASSERT_TRUE(device);
    EXPECT_EQ(device->article, "[2J60");
    EXPECT_EQ(device->name, "Gleis]0;ownedbox");
    EXPECT_EQ(device->nickname, "Nick1m");
}

TEST(StatusData, PacketsJoinInPacketNumberOrder) {
    StatusDataPackets packets;
    packets.add(0x0302, cs2::RawBytes{2, {'c', 'd'}});
    packets.add(0x0301, cs2::RawBytes{2, {'a', 'b'}});
    packets.add(0x0302, cs2::RawBytes{1, {'C'}});
    EXPECT_EQ(packets.assemble(), (std::vector<std::uint8_t>{'a', 'b', 'C'}));
}

TEST(StatusData, DeviceThatDoesNotAnswerIsReportedNotFatal) {
    Bench bench;
    bench.session.statusData().setPolicy({40ms, 1});
    std::optional<QStringList> problems;
    bench.session.statusData().read({0x11223344, 1, 0, 0x0040},
                                    [&](const DeviceDescription&, const QStringList& p) { problems = p; });
    ASSERT_TRUE(waitFor([&] { return problems.has_value(); }));
    ASSERT_EQ(problems->size(), 1);
    EXPECT_TRUE(problems->front().contains(QStringLiteral("0x11223344")));
}

} // namespace
} // namespace stellwerk::station::test
