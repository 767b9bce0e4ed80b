// The facts with concrete values from shared/docs/cs2-field-notes.md (FieldNotes_*), checked through
// the CS2 codec next to the document examples (DocumentChapter*Test.cpp).
//
// Example lines are quoted as the document prints them, comment included (parseFrame takes text after
// the data bytes as a comment). All frames use the document's hash 0x4711 unless a test says otherwise.

#include "DocumentExamplesSupport.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Crc16.h"
#include "cs2/Fields.h"
#include "cs2/FrameReport.h"
#include "cs2/Hash.h"
#include "cs2/Header.h"
#include "cs2/LocId.h"
#include "cs2/Messages.h"
#include "cs2/SpeedSteps.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2 {
namespace {

using test::configRequest;
using test::contains;
using test::corpusFile;
using test::decodeAs;
using test::described;
using test::expectRoundTrip;
using test::frameText;

// ===== Field notes: framing ==========================================================================

TEST(FieldNotes_Framing, NetworkFormByteLayout) {
    // byte 0 = prio << 1 | command >> 7, byte 1 = command << 1 | response, bytes 2-3 hash, byte 4 DLC.
    const CanFrame f{cs2::makeId(3, 0x21, true, 0x0301), 8, {1, 2, 3, 4, 5, 6, 7, 8}};
    const auto bytes = f.toNetwork();
    EXPECT_EQ(bytes[0], 0x06);
    EXPECT_EQ(bytes[1], 0x43);
    EXPECT_EQ(bytes[2], 0x03);
    EXPECT_EQ(bytes[3], 0x01);
    EXPECT_EQ(bytes[4], 8);
    EXPECT_EQ(bytes[12], 8);
}

TEST(FieldNotes_Framing, DlcAbove8IsRefused) {
    std::array<std::uint8_t, CanFrame::NetworkSize> bytes{0x00, 0x00, 0x47, 0x11, 0x09};
    const auto result = decode(CanFrame::fromNetwork(bytes));
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, DecodeErrorKind::DlcOutOfRange);
    EXPECT_TRUE(contains(result.error().message(), "DLC 9 is above 8")) << result.error().message();
}

// ===== Field notes: addresses ========================================================================

TEST(FieldNotes_Addresses, MmAccessory1Is0x3000) {
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2Accessory, 1), LocId(0x3000));
    EXPECT_EQ(LocId(0x3000).address(), 1u);
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2Accessory, 1024), LocId(0x33FF));
    EXPECT_FALSE(LocId::fromAddress(Protocol::Mm2Accessory, 0).has_value());
    EXPECT_EQ(described("00164711 6 00 00 30 00 01 01", "address"), "1");
    expectRoundTrip("00164711 6 00 00 30 00 01 01");
}

TEST(FieldNotes_Addresses, DccAccessory1Is0x3800) {
    EXPECT_EQ(LocId::fromAddress(Protocol::DccAccessory, 1), LocId(0x3800));
    EXPECT_EQ(LocId(0x3800).address(), 1u);
    EXPECT_EQ(LocId::fromAddress(Protocol::DccAccessory, 2048), LocId(0x3FFF));
    EXPECT_FALSE(LocId::fromAddress(Protocol::DccAccessory, 0).has_value());
    EXPECT_EQ(described("00164711 6 00 00 38 00 01 01", "address"), "1");
}

TEST(FieldNotes_Addresses, DocumentsMm2Accessory3CountsFromZero) {
    // The document's "MM2 Zubehör mit Adresse 3" = 0x3003 is offset 3, keyboard number 4.
    EXPECT_EQ(LocId(0x3003).offset(), 3u);
    EXPECT_EQ(LocId(0x3003).address(), 4u);
    EXPECT_EQ(described("00164711 6 00 00 30 03 01 01", "address"), "4");
}

TEST(FieldNotes_Addresses, LocoAddressesAreOffsetsFromTheRangeBase) {
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2, 72), LocId(0x0048));
    EXPECT_EQ(LocId::fromAddress(Protocol::Dcc, 3), LocId(0xC003));
    EXPECT_EQ(LocId::fromAddress(Protocol::Mfx, 5), LocId(0x4005));
    EXPECT_EQ(LocId::fromAddress(Protocol::Sx1, 3), LocId(0x0803));
}

// ===== Field notes: hash ============================================================================

TEST(FieldNotes_Hash, CommonImplementationFormula) {
    // x = uid_hi16 ^ uid_lo16; ((x << 3) & 0xFF00) | 0x0300 | (x & 0x7F).
    for (std::uint32_t uid : {0x00000000u, 0x43533208u, 0x4743F5DAu, 0xFFFA8C43u, 0x12345678u, 0xFFFFFFFFu}) {
        const std::uint16_t x = std::uint16_t((uid >> 16) ^ (uid & 0xFFFF));
        const std::uint16_t expected = std::uint16_t(((x << 3) & 0xFF00) | 0x0300 | (x & 0x7F));
        EXPECT_EQ(hashFromUid(uid), expected) << std::hex << uid;
        EXPECT_TRUE(hasCs2Marker(hashFromUid(uid)));
    }
}

TEST(FieldNotes_Hash, HashesWithoutMarkerStillDecode) {
    // MS2s send plain x, and answer loco streams with hash 0: never validate a peer's hash.
    EXPECT_FALSE(hasCs2Marker(0x0000));
    EXPECT_FALSE(hasCs2Marker(0x715B));
    Message envelope;
    const auto speed = decodeAs<LocoSpeed>("0009715B 6 00 00 40 05 01 F4", &envelope);
    EXPECT_EQ(envelope.hash, 0x715B);
    EXPECT_EQ(speed.speed, 500);
    EXPECT_EQ(decodeAs<LocoSpeed>("00090000 4 00 00 40 05").loco.value(), 0x00004005u);
    expectRoundTrip("0009715B 6 00 00 40 05 01 F4");
}

// ===== Field notes: config data =======================================================================

TEST(FieldNotes_ConfigData, RequestKeysAreZeroPadded) {
    // The notes list "lokstat" where the document's table says "loksstat"; both are just eight bytes.
    for (std::string_view key :
         {"loks", "mags", "fs", "gbs", "gbs-2", "lokstat", "loksstat", "magstat", "gbsstat"}) {
        const std::string text = configRequest("00404711", key);
        SCOPED_TRACE(text);
        const auto request = decodeAs<ConfigDataRequest>(text);
        EXPECT_EQ(request.text(), key);
        for (std::size_t i = key.size(); i < 8; ++i)
            EXPECT_EQ(request.filename[i], '\0');
        expectRoundTrip(text);
    }
}

TEST(FieldNotes_ConfigData, LoknamenFollowUpFrame) {
    // "loknamen" needs a second frame with ASCII "<first> <count>", here the first two locos.
    EXPECT_EQ(decodeAs<ConfigDataRequest>(configRequest("00404711", "loknamen")).text(), "loknamen");
    EXPECT_EQ(decodeAs<ConfigDataRequest>(configRequest("00404711", "0 2")).text(), "0 2");
    expectRoundTrip(configRequest("00404711", "0 2"));
}

TEST(FieldNotes_ConfigData, LokinfoNameInTwoFrames) {
    // "lokinfo" is followed by two frames carrying a 16-character loco name; full frames have no NUL.
    const std::string first = configRequest("00404711", "Dampflok");
    const std::string second = configRequest("00404711", " BR 01.1");
    EXPECT_EQ(std::string(decodeAs<ConfigDataRequest>(first).text()) +
                  std::string(decodeAs<ConfigDataRequest>(second).text()),
              "Dampflok BR 01.1");
    expectRoundTrip(first);
    expectRoundTrip(second);
}

TEST(FieldNotes_ConfigData, CrcCheckValue) {
    // CCITT-FALSE check value: "123456789" -> 0x29B1.
    const std::string_view check = "123456789";
    std::vector<std::uint8_t> bytes(check.begin(), check.end());
    EXPECT_EQ(crc16(bytes), 0x29B1);
}

TEST(FieldNotes_ConfigData, CorpusStreamTestVector) {
    // can2udp's logged stream: header DLC 7 (length 0x5F, CRC 0x2170, 0x7B), then 12 data frames.
    std::ifstream in(corpusFile("GBert__railroad/can2udp/src/example_zlib.txt"));
    ASSERT_TRUE(in.is_open());
    std::vector<CanFrame> frames;
    for (std::string line; std::getline(in, line);) {
        if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
        const auto parsed = can::parseFrame(line);
        ASSERT_TRUE(parsed.hasValue()) << line << ": " << parsed.error();
        frames.push_back(parsed->frame);
    }
    ASSERT_EQ(frames.size(), 13u);

    const auto header = decode(frames[0]);
    ASSERT_TRUE(header.hasValue());
    const auto* head = std::get_if<ConfigDataStream>(&header->body);
    ASSERT_NE(head, nullptr);
    EXPECT_EQ(head->form, ConfigDataStream::Form::BroadcastHeader);
    EXPECT_EQ(head->length, 0x5Fu);
    EXPECT_EQ(head->crc, 0x2170);
    EXPECT_EQ(head->extra, 0x7B);
    EXPECT_EQ(header->hash, 0x0300);
    EXPECT_EQ(encode(*header), frames[0]);

    std::vector<std::uint8_t> payload;
    for (std::size_t i = 1; i < frames.size(); ++i) {
        const auto result = decode(frames[i]);
        ASSERT_TRUE(result.hasValue()) << i;
        const auto* data = std::get_if<ConfigDataStream>(&result->body);
        ASSERT_NE(data, nullptr) << i;
        EXPECT_EQ(data->form, ConfigDataStream::Form::Data);
        payload.insert(payload.end(), data->data.begin(), data->data.end());
        EXPECT_EQ(encode(*result), frames[i]) << i;
    }
    ASSERT_EQ(payload.size(), 96u);
    EXPECT_EQ(crc16(payload), 0x2170);
    EXPECT_EQ(crc16(std::span(payload.data(), 95)), 0x772F);
    // Compressed payload: u32 BE uncompressed size (170), then a zlib stream (78 9C).
    EXPECT_EQ((payload[0] << 24) | (payload[1] << 16) | (payload[2] << 8) | payload[3], 170);
    EXPECT_EQ(payload[4], 0x78);
    EXPECT_EQ(payload[5], 0x9C);
}

// ===== Field notes: status data and readings =========================================================

TEST(FieldNotes_StatusData, PacketHashesAndEndFrames) {
    // Data frames: hash 0x0300 + packet number, first packet 0x0301.
    for (std::uint16_t packet = 1; packet <= 3; ++packet)
        EXPECT_EQ(hashFromPacketNumber(packet), 0x0300 + packet);
    // End frame DLC 6 with the count; some devices send DLC 5 without it.
    const auto withCount = decodeAs<StatusDataConfig>("003B4711 6 47 43 F5 DA 00 04");
    EXPECT_EQ(withCount.form, StatusDataConfig::Form::End);
    EXPECT_EQ(withCount.packetCount, 4);
    const auto withoutCount = decodeAs<StatusDataConfig>("003B4711 5 47 43 F5 DA 00");
    EXPECT_EQ(withoutCount.form, StatusDataConfig::Form::End);
    EXPECT_EQ(withoutCount.device, 0x4743F5DAu);
    EXPECT_FALSE(withoutCount.packetCount.has_value());
    expectRoundTrip("003B4711 6 47 43 F5 DA 00 04");
    expectRoundTrip("003B4711 5 47 43 F5 DA 00");
    // A shorter last data frame is still a packet.
    const auto shortLast = decodeAs<StatusDataConfig>("003B0305 3 41 00 00");
    EXPECT_EQ(shortLast.form, StatusDataConfig::Form::Packet);
    EXPECT_EQ(shortLast.packet.size, 3);
    expectRoundTrip("003B0305 3 41 00 00");
}

TEST(FieldNotes_StatusData, Gleisbox60113PingAnswer) {
    // Gleisbox 60113: UID 0x4743F5DA, device type 0x0010 (the version bytes here are illustrative).
    const std::string text = "00314711 8 47 43 F5 DA 01 27 00 10";
    const auto ping = decodeAs<Ping>(text);
    ASSERT_TRUE(ping.identity.has_value());
    EXPECT_EQ(ping.identity->uid, 0x4743F5DAu);
    EXPECT_EQ(ping.identity->deviceType, 0x0010);
    EXPECT_EQ(described(text, "deviceName"), "Gleisbox 60112/60113");
    expectRoundTrip(text);
}

// One reading description of the field notes' Gleisbox 60113, as the status-data stream carries it.
struct ReadingDescription {
    std::uint8_t channel;
    std::int8_t power;
    std::uint16_t zero;
    std::array<std::uint16_t, 4> ends;
    std::string name, start, end, unit;
};

std::vector<std::uint8_t> serialise(const ReadingDescription& d) {
    std::vector<std::uint8_t> out{d.channel, std::uint8_t(d.power), 0x30, 0xF0, 0xE0,
                                  0xC0}; // colours illustrative
    auto u16 = [&](std::uint16_t v) {
        out.push_back(std::uint8_t(v >> 8));
        out.push_back(std::uint8_t(v));
    };
    u16(d.zero);
    for (auto e : d.ends)
        u16(e);
    for (const auto* s : {&d.name, &d.start, &d.end, &d.unit}) {
        out.insert(out.end(), s->begin(), s->end());
        out.push_back(0);
    }
    return out;
}

// Sends the bytes as status-data packets (hash = packet number), decodes them back and reassembles.
std::vector<std::uint8_t> throughPackets(const std::vector<std::uint8_t>& bytes) {
    std::vector<std::uint8_t> out;
    for (std::size_t offset = 0, packet = 1; offset < bytes.size(); offset += 8, ++packet) {
        std::vector<std::uint8_t> chunk(8, 0);
        std::copy(bytes.begin() + long(offset), bytes.begin() + long(std::min(bytes.size(), offset + 8)),
                  chunk.begin());
        char id[9];
        std::snprintf(id, sizeof id, "003B%04X", hashFromPacketNumber(std::uint16_t(packet)));
        const std::string text = frameText(id, chunk);
        Message envelope;
        const auto decoded = decodeAs<StatusDataConfig>(text, &envelope);
        EXPECT_EQ(decoded.form, StatusDataConfig::Form::Packet) << text;
        EXPECT_EQ(packetNumberFromHash(envelope.hash), packet) << text;
        const auto view = decoded.packet.view();
        out.insert(out.end(), view.begin(), view.end());
    }
    return out;
}

// Displayed value = start + (raw - zero) * (end - start) / (rangeEnd4 - zero).
double displayed(const std::vector<std::uint8_t>& description, std::uint16_t raw) {
    auto u16 = [&](std::size_t i) { return std::uint16_t((description[i] << 8) | description[i + 1]); };
    const std::uint16_t zero = u16(6);
    const std::uint16_t end4 = u16(14);
    std::vector<std::string> strings;
    std::string current;
    for (std::size_t i = 16; i < description.size() && strings.size() < 4; ++i) {
        if (description[i] == 0) {
            strings.push_back(current);
            current.clear();
        } else {
            current.push_back(char(description[i]));
        }
    }
    const double start = std::stod(strings.at(1));
    const double end = std::stod(strings.at(2));
    return start + (double(raw) - zero) * (end - start) / (double(end4) - zero);
}

TEST(FieldNotes_StatusData, Gleisbox60113ReadingsScale) {
    const ReadingDescription track{1,       -3,     0x000F, {0x0670, 0x06C2, 0x0767, 0x080C},
                                   "TRACK", "0.00", "2.50", "A"};
    const ReadingDescription volt{3,      -3,      0x0000,  {0x039D, 0x04B2, 0x0A1E, 0x0C49},
                                  "VOLT", "10.00", "27.00", "Volt"};
    const ReadingDescription temp{4, 0, 0x0000, {0x006B, 0x00A4, 0x00CD, 0x00DB}, "TEMP", "0.0", "80.0", "C"};

    // The readings arrive as system status answers (2.12) on the description's query channel.
    const auto current = decodeAs<SystemStatus>("00014711 8 47 43 F5 DA 0B 01 00 2E");
    EXPECT_EQ(current.device, 0x4743F5DAu);
    EXPECT_EQ(current.channel, track.channel);
    ASSERT_TRUE(current.value.has_value());
    EXPECT_EQ(*current.value, 46);
    const auto voltage = decodeAs<SystemStatus>("00014711 8 47 43 F5 DA 0B 03 08 81");
    EXPECT_EQ(voltage.channel, volt.channel);
    EXPECT_EQ(voltage.value, 2177);
    const auto temperature = decodeAs<SystemStatus>("00014711 8 47 43 F5 DA 0B 04 00 28");
    EXPECT_EQ(temperature.channel, temp.channel);
    EXPECT_EQ(temperature.value, 40);

    const auto trackBytes = throughPackets(serialise(track));
    EXPECT_EQ(trackBytes.size() % 8, 0u);
    EXPECT_NEAR(displayed(trackBytes, *current.value), 0.038, 0.0005);
    EXPECT_NEAR(displayed(throughPackets(serialise(volt)), voltage.value.value_or(0)), 21.8, 0.05);
    EXPECT_NEAR(displayed(throughPackets(serialise(temp)), temperature.value.value_or(0)), 14.6, 0.05);
}

TEST(FieldNotes_StatusData, WriteConfigValueAndAnswer) {
    // System 0x0B: DLC 8 without response bit writes a config value; the answer is DLC 7 with 1 or 0.
    Message envelope;
    const auto write = decodeAs<SystemStatus>("00004711 8 47 43 F5 DA 0B 05 01 F4", &envelope);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(write.value, 500);
    EXPECT_EQ(decodeAs<SystemStatus>("00014711 7 47 43 F5 DA 0B 05 01").accepted, true);
    EXPECT_EQ(decodeAs<SystemStatus>("00014711 7 47 43 F5 DA 0B 05 00").accepted, false);
}

// ===== Field notes: devices and start-up ============================================================

TEST(FieldNotes_Devices, PingDeviceTypesSeen) {
    EXPECT_EQ(deviceTypeName(0x0011), "Gleisbox 60116");
    for (std::uint16_t ms2 = 0x0030; ms2 <= 0x0034; ++ms2)
        EXPECT_EQ(deviceTypeName(ms2), "Mobile Station 2") << ms2;
    EXPECT_EQ(deviceTypeName(0x0040), "Link S88");
    EXPECT_EQ(deviceTypeName(0xEEEE), "CS2 software (PC)");
    EXPECT_EQ(deviceTypeName(0x1234), "unknown device type");
}

TEST(FieldNotes_Devices, GleisboxGoFrame) {
    // can2lan wakes a bare Gleisbox with "0x1B DLC5 00 00 00 00 11": CAN bootloader, UID 0, 0x11 = go.
    const std::string go = "00364711 5 00 00 00 00 11";
    Message envelope;
    const auto boot = decodeAs<BootloaderCan>(go, &envelope);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(boot.raw.size, 5);
    EXPECT_EQ(boot.raw.bytes[4], 0x11);
    EXPECT_EQ(described(go, "uid"), "0");
    EXPECT_EQ(described(go, "mode"), "start-application");
    expectRoundTrip(go);
    // ... then system 0x08 with 0x07: enable MM2, mfx and DCC.
    const auto enable = decodeAs<TrackProtocols>("00004711 6 00 00 00 00 08 07");
    EXPECT_EQ(enable.target, 0x00000000u);
    EXPECT_EQ(enable.mask, 0x07);
    EXPECT_EQ(described("00004711 6 00 00 00 00 08 07", "protocols"), "mm2,mfx,dcc");
    expectRoundTrip("00004711 6 00 00 00 00 08 07");
}

// ===== Field notes: S88 feedback =====================================================================

TEST(FieldNotes_S88, EventAnswerFields) {
    // Device id, contact, old state, new state, time in 10 ms units; Link-S88 buses count contacts by
    // thousands (contact 1001 = bus 1, contact 1).
    const std::string text = "00234711 8 00 40 03 E9 01 00 01 2C";
    const auto event = decodeAs<S88Event>(text);
    EXPECT_EQ(event.device, 0x0040);
    EXPECT_EQ(event.contact, 1001);
    ASSERT_TRUE(event.change.has_value());
    EXPECT_EQ(event.change->oldState, 1);
    EXPECT_EQ(event.change->newState, 0);
    EXPECT_EQ(event.change->time10ms, 300);
    EXPECT_EQ(described(text, "timeMs"), "3000");
    expectRoundTrip(text);
}

} // namespace
} // namespace stellwerk::cs2
