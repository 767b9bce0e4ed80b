// Sending then receiving gives back the same file, in every format and at every size around the
// frame boundaries; and the frames look like a CS2's.

#include "ConfigStreamTestSupport.h"
#include "cs2/Crc16.h"
#include "cs2config/ConfigStreamPayload.h"
#include "cs2config/ConfigStreamRequestCollector.h"
#include "cs2config/ConfigStreamSender.h"

#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::cs2config;
using test::receiveAll;
using test::singleFile;

namespace {

const std::size_t Sizes[] = {0,  1,  2,  3,  4,  5,    6,    7,    8,    9,    15,
                             16, 17, 63, 64, 65, 1000, 4095, 4096, 4097, 65537};

// Lines of .cs2-like text, `size` bytes long.
std::string textOfSize(std::size_t size) {
    std::string text;
    for (unsigned i = 0; text.size() < size; ++i)
        text += i % 5 == 0 ? "lok\n" : " .name=Lok " + std::to_string(i * 37) + (i % 3 ? "\n" : " \n");
    text.resize(size);
    return text;
}

// Binary bytes with zeros inside, none at the end, and no zlib header at offset 4.
std::string binaryOfSize(std::size_t size) {
    std::string bytes;
    std::uint32_t state = 0x12345678;
    for (std::size_t i = 0; i < size; ++i) {
        state = state * 1103515245 + 12345;
        bytes += char(i % 13 == 1 ? 0 : (state >> 16) | 1);
    }
    if (size > 4)
        bytes[4] = 'B';
    return bytes;
}

std::string roundTrip(const std::string& contents, StreamFormat format, StreamAddress address) {
    return singleFile(receiveAll(streamFrames(contents, format, address))).contents;
}

} // namespace

TEST(ConfigStreamRoundTrip, CompressedAtEverySize) {
    for (std::size_t size : Sizes) {
        EXPECT_EQ(roundTrip(textOfSize(size), StreamFormat::Compressed, StreamAddress::reply(0x4711)),
                  textOfSize(size))
            << size;
        EXPECT_EQ(roundTrip(binaryOfSize(size), StreamFormat::Compressed, StreamAddress::broadcast(0x0300)),
                  binaryOfSize(size))
            << size;
    }
}

TEST(ConfigStreamRoundTrip, Ms2TextAtEverySize) {
    for (std::size_t size : Sizes)
        EXPECT_EQ(roundTrip(textOfSize(size), StreamFormat::Ms2Text, StreamAddress::reply(0x4711)),
                  textOfSize(size))
            << size;
}

TEST(ConfigStreamRoundTrip, BinaryAtEverySize) {
    for (std::size_t size : Sizes)
        EXPECT_EQ(roundTrip(binaryOfSize(size), StreamFormat::Binary, StreamAddress::reply(0x4711)),
                  binaryOfSize(size))
            << size;
}

TEST(ConfigStreamRoundTrip, LargeFileOfTwoMegabytes) {
    const std::string big = textOfSize(2u << 20);
    EXPECT_EQ(roundTrip(big, StreamFormat::Compressed, StreamAddress::reply(0x4711)), big);
    EXPECT_EQ(roundTrip(big, StreamFormat::Ms2Text, StreamAddress::reply(0x4711)), big);
}

TEST(ConfigStreamRoundTrip, CorpusFiles) {
    for (const char* path : {"bob123456678__TrainControl/test/lokomotive.cs2",
                             "bob123456678__TrainControl/test/magnetartikel.cs2",
                             "bob123456678__TrainControl/test/fahrstrassen.cs2",
                             "GBert__railroad/can2udp/files/maerklin/config/gleisbilder/karben.cs2",
                             "joao404__z21MaerklinCan/data/config/lokomotive.cs2"}) {
        const std::string contents = test::readCorpus(path);
        ASSERT_FALSE(contents.empty()) << path;
        EXPECT_EQ(roundTrip(contents, StreamFormat::Compressed, StreamAddress::reply(0x4711)), contents)
            << path;
    }
}

TEST(ConfigStreamRoundTrip, TheCorpusStreamIsWhatOurSenderSends) {
    // Inflate the logged broadcast and send the page again: the same 13 frames, byte for byte.
    const auto logged = test::framesOfLog("GBert__railroad/can2udp/src/example_zlib.txt");
    const auto page = singleFile(receiveAll(logged)).contents;
    const auto sent = streamFrames(page, StreamFormat::Compressed, StreamAddress::broadcast(0x0300));
    ASSERT_EQ(sent.size(), logged.size());
    for (std::size_t i = 0; i < sent.size(); ++i)
        EXPECT_EQ(can::formatDocument(sent[i]), can::formatDocument(logged[i])) << "frame " << i;
}

TEST(ConfigStreamRoundTrip, FramesHaveTheDocumentedShape) {
    const std::string contents = textOfSize(1000);
    const auto payload = streamPayload(contents, StreamFormat::Compressed);
    const auto frames = streamFrames(contents, StreamFormat::Compressed, StreamAddress::reply(0x4711));
    ASSERT_EQ(frames.size(), 1 + (payload.size() + 7) / 8);

    const auto& header = frames[0];
    EXPECT_EQ(header.id, 0x00424711u); // prio 0, command 0x21, no response bit, requester's hash
    EXPECT_EQ(header.dlc, 6);
    const std::uint32_t length = (std::uint32_t(header.data[0]) << 24) |
                                 (std::uint32_t(header.data[1]) << 16) |
                                 (std::uint32_t(header.data[2]) << 8) | header.data[3];
    EXPECT_EQ(length, payload.size()); // prefix + zlib bytes, padding excluded

    std::vector<std::uint8_t> padded;
    for (std::size_t i = 1; i < frames.size(); ++i) {
        EXPECT_EQ(frames[i].id, 0x00424711u);
        EXPECT_EQ(frames[i].dlc, 8);
        padded.insert(padded.end(), frames[i].data.begin(), frames[i].data.end());
    }
    EXPECT_TRUE(std::equal(payload.begin(), payload.end(), padded.begin()));
    EXPECT_TRUE(std::all_of(padded.begin() + std::ptrdiff_t(payload.size()), padded.end(),
                            [](std::uint8_t b) { return b == 0; }));
    EXPECT_EQ((header.data[4] << 8) | header.data[5], cs2::crc16(padded)); // CRC over the padded bytes
}

TEST(ConfigStreamRoundTrip, BroadcastHeaderHasSevenBytes) {
    const auto frames = streamFrames("x\n", StreamFormat::Compressed, StreamAddress::broadcast(0x0300));
    EXPECT_EQ(frames[0].dlc, 7);
    EXPECT_EQ(frames[0].data[6], 0x7B);
    EXPECT_EQ(
        streamFrames("x\n", StreamFormat::Compressed, StreamAddress::broadcast(0x0300, 0x01))[0].data[6], 1);
}

TEST(ConfigStreamRoundTrip, EmptyPlainFileIsAHeaderOnly) {
    const auto frames = streamFrames("", StreamFormat::Ms2Text, StreamAddress::reply(0x4711));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(can::formatDocument(frames[0]), "00424711 6 00 00 00 00 FF FF");
}

TEST(ConfigStreamRoundTrip, StreamFormatFollowsTheKey) {
    EXPECT_EQ(streamFormatForKey("loks"), StreamFormat::Compressed);
    EXPECT_EQ(streamFormatForKey("gbs-7"), StreamFormat::Compressed);
    EXPECT_EQ(streamFormatForKey("lokinfo"), StreamFormat::Ms2Text);
    EXPECT_EQ(streamFormatForKey("lokdb"), StreamFormat::Binary);
    EXPECT_EQ(streamFormatForKey("whatever"), StreamFormat::Compressed);
}

// A whole conversation: the requester asks, the station recognises the request and answers with
// its acknowledgement and the stream, the requester stores the file under the requested key.
TEST(ConfigStreamRoundTrip, RequestAnswerConversation) {
    const std::string lokinfo = "[lokomotive]\nlok\n .uid=0x4005\n .name=M4\n .adresse=0x9\n .typ=mfx\n";
    const auto asked = ConfigRequest::locoInfo("M4").frames(0x4711);

    ConfigRequestCollector station;
    std::optional<CollectedConfigRequest> heard;
    for (const auto& f : asked)
        if (auto request = station.feed(*cs2::decode(f)))
            heard = request;
    ASSERT_TRUE(heard.has_value());
    EXPECT_EQ(heard->request.qualifier(), "M4");
    const auto answer = answerFrames(heard->request, lokinfo, heard->hash);
    ASSERT_EQ(answer.size(), 3 + 1 + (payload::padLines(lokinfo).size() + 7) / 8);
    EXPECT_TRUE(cs2::isResponse(answer[0]));

    ConfigRequestCollector requesterSide;
    ConfigStreamReceiver receiver;
    std::vector<StreamOutcome> outcomes;
    for (const auto& f : answer) {
        if (auto ack = requesterSide.feed(*cs2::decode(f)))
            receiver.expectFile(ack->request.key(), ack->hash);
        for (auto& outcome : receiver.feed(f))
            outcomes.push_back(std::move(outcome));
    }
    const auto file = singleFile(outcomes);
    EXPECT_EQ(file.key, "lokinfo");
    EXPECT_FALSE(file.compressed);
    EXPECT_EQ(file.contents, lokinfo);
}
