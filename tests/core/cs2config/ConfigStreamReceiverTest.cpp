// Receiving config-data streams (command 0x21, document 7.2): the corpus log, every way a stream
// can arrive broken, and progress while it arrives.

#include "cs2config/ConfigStreamReceiver.h"

#include "ConfigStreamTestSupport.h"
#include "cs2/Crc16.h"
#include "cs2config/ConfigStreamPayload.h"
#include "cs2config/ConfigStreamSender.h"
#include "cs2config/TrackPage.h"

#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::cs2config;
using test::bytesOf;
using test::frame;
using test::receiveAll;
using test::singleError;
using test::singleFile;

namespace {

constexpr const char* CorpusLog = "GBert__railroad/can2udp/src/example_zlib.txt";

std::size_t count(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
        ++n;
    return n;
}

std::vector<can::CanFrame> corpusStream() {
    return test::framesOfLog(CorpusLog);
}

can::CanFrame dataFrame(std::uint16_t hash, std::array<std::uint8_t, 8> bytes = {}) {
    cs2::ConfigDataStream body;
    body.data = bytes;
    return cs2::encode(cs2::Message{0, false, hash, body});
}

can::CanFrame headerFrame(std::uint16_t hash, std::uint32_t length, std::uint16_t crc) {
    cs2::ConfigDataStream body;
    body.form = cs2::ConfigDataStream::Form::Header;
    body.length = length;
    body.crc = crc;
    return cs2::encode(cs2::Message{0, false, hash, body});
}

std::vector<can::CanFrame> framesFor(const std::vector<std::uint8_t>& payload, std::uint16_t hash = 0x4711) {
    return payloadFrames(payload, StreamAddress::reply(hash));
}

} // namespace

// ---- The logged stream of the corpus ------------------------------------------------------------

TEST(ConfigStreamReceiver, CorpusLogReassemblesToTheGleisbildPage) {
    const auto file = singleFile(receiveAll(corpusStream()));
    EXPECT_TRUE(file.broadcast);
    EXPECT_EQ(file.broadcastValue, 0x7B);
    EXPECT_EQ(file.hash, 0x0300);
    EXPECT_EQ(file.length, 0x5Fu);
    EXPECT_EQ(file.crc, 0x2170);
    EXPECT_EQ(file.streamBytes.size(), 96u);
    EXPECT_EQ(cs2::crc16(file.streamBytes), 0x2170);
    EXPECT_EQ(cs2::crc16(std::span(file.streamBytes).first(95)), 0x772F);
    EXPECT_TRUE(file.compressed);
    EXPECT_EQ(file.key, "");
    EXPECT_EQ(file.contents.size(), 170u);
    EXPECT_EQ(file.contents.rfind("[gleisbildseite]\n", 0), 0u) << file.contents;
    EXPECT_EQ(count(file.contents, ".typ=gerade"), 3u) << file.contents;
}

TEST(ConfigStreamReceiver, CorpusLogFedAsDecodedMessages) {
    ConfigStreamReceiver receiver;
    std::vector<StreamOutcome> outcomes;
    for (const auto& f : corpusStream()) {
        const auto message = cs2::decode(f);
        ASSERT_TRUE(message.hasValue());
        for (auto& outcome : receiver.feed(std::get<cs2::ConfigDataStream>(message->body), message->hash))
            outcomes.push_back(std::move(outcome));
    }
    EXPECT_EQ(singleFile(outcomes).contents.size(), 170u);
}

TEST(ConfigStreamReceiver, Cs3LengthCountingThePaddingIsAccepted) {
    auto frames = corpusStream();
    frames[0] = frame("00420300 7 00 00 00 60 21 70 7B"); // 96 instead of 95
    const auto file = singleFile(receiveAll(frames));
    EXPECT_EQ(file.length, 96u);
    EXPECT_EQ(file.contents.size(), 170u);
}

TEST(ConfigStreamReceiver, ResponseHeaderCarriesTheRequestedKey) {
    auto frames = corpusStream();
    for (auto& f : frames)
        f.id = (f.id & 0xFFFF0000) | 0x4711;
    frames[0] = frame("00424711 6 00 00 00 5F 21 70");
    ConfigStreamReceiver receiver;
    receiver.expectFile("gbs-0", 0x1234); // another requester's: not this stream
    receiver.expectFile("gbs-0", 0x4711);
    const auto file = singleFile(receiveAll(receiver, frames));
    EXPECT_FALSE(file.broadcast);
    EXPECT_EQ(file.key, "gbs-0");
    EXPECT_EQ(file.contents.size(), 170u);
}

TEST(ConfigStreamReceiver, TheExpectationIsUsedOnce) {
    ConfigStreamReceiver receiver;
    receiver.expectFile("gbs", 0x0300);
    EXPECT_EQ(singleFile(receiveAll(receiver, corpusStream())).key, "gbs");
    EXPECT_EQ(singleFile(receiveAll(receiver, corpusStream())).key, "");
}

// ---- Plain streams ------------------------------------------------------------------------------

TEST(ConfigStreamReceiver, Ms2TextStreamLosesItsLinePadding) {
    const std::string text = "[lokomotive]\nlok\n .nr=3\n .name=MaK 1206 ACTS\nnumloks\n .wert=8\n";
    const auto file =
        singleFile(receiveAll(streamFrames(text, StreamFormat::Ms2Text, StreamAddress::reply(1))));
    EXPECT_FALSE(file.compressed);
    EXPECT_EQ(file.contents, text);
    EXPECT_EQ(file.length, payload::padLines(text).size());
}

// Issue 11 (found by fuzzing): "x " at bytes 4-5 looks like a zlib header after a size prefix, and the
// receiver refused this plain text as a broken compressed file. The requested key says the format.
TEST(ConfigStreamReceiver, PlainTextThatLooksCompressedFollowsTheKeysFormat) {
    const std::string text = "abcdx 1\n";
    ASSERT_TRUE(payload::isCompressed(streamPayload(text, StreamFormat::Ms2Text)));
    ConfigStreamReceiver receiver;
    receiver.expectFile("lokinfo", 1);
    const auto file =
        singleFile(receiveAll(receiver, streamFrames(text, StreamFormat::Ms2Text, StreamAddress::reply(1))));
    EXPECT_FALSE(file.compressed);
    EXPECT_EQ(file.contents, text);
}

TEST(ConfigStreamReceiver, WithoutAKeyWhatDoesNotInflateIsPlainText) {
    const std::string text = "abcdx 1\n";
    const auto file =
        singleFile(receiveAll(streamFrames(text, StreamFormat::Ms2Text, StreamAddress::broadcast(1))));
    EXPECT_FALSE(file.compressed);
    EXPECT_EQ(file.contents, text);
}

TEST(ConfigStreamReceiver, BinaryKeyKeepsTrailingZeroBytes) {
    const std::string bytes("\x01\x02\0\0\0\0\0\0", 8);
    ConfigStreamReceiver receiver;
    receiver.expectFile("lokdb", 1);
    const auto file =
        singleFile(receiveAll(receiver, streamFrames(bytes, StreamFormat::Binary, StreamAddress::reply(1))));
    EXPECT_EQ(file.contents, bytes);
}

TEST(ConfigStreamReceiver, EmptyStreamCompletesWithItsHeader) {
    ConfigStreamReceiver receiver;
    const auto outcomes = receiver.feed(headerFrame(0x4711, 0, 0xFFFF));
    const auto file = singleFile(outcomes);
    EXPECT_EQ(file.contents, "");
    EXPECT_FALSE(file.compressed);
    EXPECT_FALSE(receiver.collecting());
}

// ---- Broken streams -----------------------------------------------------------------------------

TEST(ConfigStreamReceiver, CrcMismatchNamesBothValues) {
    auto frames = corpusStream();
    frames[5].data[2] ^= 0x01;
    const auto error = singleError(receiveAll(frames));
    EXPECT_EQ(error.kind, StreamErrorKind::CrcMismatch);
    EXPECT_EQ(
        error.message.rfind("broadcast stream (hash 0x0300): CRC mismatch: the header announces 0x2170, "
                            "the 96 received bytes give 0x",
                            0),
        0u)
        << error.message;
}

TEST(ConfigStreamReceiver, CrcWithoutThePaddingIsRejectedWithAHint) {
    auto frames = corpusStream();
    frames[0] = frame("00420300 7 00 00 00 5F 77 2F 7B");
    const auto error = singleError(receiveAll(frames));
    EXPECT_EQ(error.kind, StreamErrorKind::CrcMismatch);
    EXPECT_EQ(error.message,
              "broadcast stream (hash 0x0300): CRC mismatch: the header announces 0x772F, the 96 "
              "received bytes give 0x2170 (the header's CRC covers the 95 bytes without the zero "
              "padding)");
}

TEST(ConfigStreamReceiver, EmptyStreamWithAWrongCrc) {
    const auto error = singleError(receiveAll({headerFrame(0x4711, 0, 0x1234)}));
    EXPECT_EQ(error.kind, StreamErrorKind::CrcMismatch);
    EXPECT_EQ(error.message,
              "stream (hash 0x4711): CRC mismatch: the header announces 0x1234, the 0 received "
              "bytes give 0xFFFF");
}

TEST(ConfigStreamReceiver, InflatedSizeDifferentFromThePrefix) {
    auto payload = payload::compress("[gleisbild]\nversion\n");
    payload[3] = 99;
    ConfigStreamReceiver receiver;
    receiver.expectFile("gbs", 0x4711);
    const auto error = singleError(receiveAll(receiver, framesFor(payload)));
    EXPECT_EQ(error.kind, StreamErrorKind::SizeMismatch);
    EXPECT_EQ(error.message,
              "stream for 'gbs' (hash 0x4711): the file inflates to 20 bytes, its size prefix announces 99");
}

TEST(ConfigStreamReceiver, MoreDataThanAnnounced) {
    auto frames = corpusStream();
    frames.push_back(frames.back());
    frames.push_back(frames.back()); // reported once
    const auto outcomes = receiveAll(frames);
    ASSERT_EQ(outcomes.size(), 2u);
    EXPECT_TRUE(outcomes[0].hasValue());
    ASSERT_FALSE(outcomes[1].hasValue());
    EXPECT_EQ(outcomes[1].error().kind, StreamErrorKind::MoreDataThanAnnounced);
    EXPECT_EQ(outcomes[1].error().message,
              "broadcast stream (hash 0x0300): a data frame arrived after the 95 "
              "announced bytes were complete; dropped");
}

TEST(ConfigStreamReceiver, DamagedZlibStreamWithAGoodCrc) {
    auto payload = payload::compress(std::string(300, 'g'));
    payload[7] ^= 0x55;
    payload[8] ^= 0x55;
    const auto error = singleError(receiveAll(framesFor(payload)));
    EXPECT_EQ(error.kind, StreamErrorKind::InflateFailed);
    EXPECT_EQ(error.message.rfind("stream (hash 0x4711): the zlib stream is damaged: ", 0), 0u)
        << error.message;
}

TEST(ConfigStreamReceiver, ZlibStreamCutShortInsideTheAnnouncedLength) {
    auto payload = payload::compress(std::string(300, 'g') + "x");
    payload.resize(payload.size() - 3);
    const auto error = singleError(receiveAll(framesFor(payload)));
    EXPECT_EQ(error.kind, StreamErrorKind::InflateFailed);
}

TEST(ConfigStreamReceiver, HeaderAboveTheLimitIsRefusedAndItsDataDropped) {
    ConfigStreamReceiver receiver(StreamLimits{1000});
    std::vector<StreamOutcome> outcomes = receiver.feed(headerFrame(0x4711, 1001, 0));
    const auto error = singleError(outcomes);
    EXPECT_EQ(error.kind, StreamErrorKind::TooLarge);
    EXPECT_EQ(error.message,
              "stream (hash 0x4711): the header announces 1001 bytes, above the limit of 1000; its "
              "data frames are dropped");
    EXPECT_TRUE(receiver.feed(dataFrame(0x4711)).empty());
    EXPECT_TRUE(receiver.feed(dataFrame(0x4711)).empty());
    EXPECT_FALSE(receiver.finish().has_value());
}

TEST(ConfigStreamReceiver, FileAboveTheLimitIsRefusedBeforeInflating) {
    // 4 MiB of zeros: a small stream that would inflate far beyond the 1 MiB limit.
    const auto frames = framesFor(payload::compress(std::string(4u << 20, '\0')));
    const auto error = singleError(receiveAll(frames, StreamLimits{1u << 20}));
    EXPECT_EQ(error.kind, StreamErrorKind::TooLarge);
    EXPECT_EQ(error.message,
              "stream (hash 0x4711): the file announces 4194304 bytes, above the limit of 1048576");
}

TEST(ConfigStreamReceiver, DataFrameWithoutHeader) {
    ConfigStreamReceiver receiver;
    const auto error = singleError(receiver.feed(dataFrame(0x4711)));
    EXPECT_EQ(error.kind, StreamErrorKind::DataWithoutHeader);
    EXPECT_EQ(error.message,
              "stream (hash 0x4711): a data frame arrived without a header (DLC 6 or 7) before "
              "it; dropped up to the next header");
    EXPECT_TRUE(receiver.feed(dataFrame(0x4711)).empty()); // the rest of that stream: reported once
    EXPECT_EQ(singleFile(receiveAll(receiver, corpusStream())).contents.size(), 170u);
}

TEST(ConfigStreamReceiver, NewHeaderInsideAStreamAbortsIt) {
    const auto corpus = corpusStream();
    std::vector<can::CanFrame> frames(corpus.begin(), corpus.begin() + 4);
    frames.insert(frames.end(), corpus.begin(), corpus.end());
    const auto outcomes = receiveAll(frames);
    ASSERT_EQ(outcomes.size(), 2u);
    ASSERT_FALSE(outcomes[0].hasValue());
    EXPECT_EQ(outcomes[0].error().kind, StreamErrorKind::Interrupted);
    EXPECT_EQ(outcomes[0].error().message,
              "broadcast stream (hash 0x0300): a new header arrived after 24 of 95 "
              "bytes; the bytes are dropped");
    ASSERT_TRUE(outcomes[1].hasValue());
    EXPECT_EQ(outcomes[1]->contents.size(), 170u);
}

TEST(ConfigStreamReceiver, NewHeaderInsideAStreamThatIsItselfComplete) {
    const auto corpus = corpusStream();
    const auto outcomes = receiveAll({corpus[0], corpus[1], headerFrame(0x0300, 0, 0xFFFF)});
    ASSERT_EQ(outcomes.size(), 2u);
    EXPECT_EQ(outcomes[0].error().kind, StreamErrorKind::Interrupted);
    EXPECT_EQ(outcomes[1]->contents, "");
}

TEST(ConfigStreamReceiver, FrameOfAnotherLengthAbortsTheStream) {
    auto frames = corpusStream();
    frames.insert(frames.begin() + 3, frame("00420300 5 01 02 03 04 05"));
    const auto outcomes = receiveAll(frames);
    ASSERT_GE(outcomes.size(), 1u);
    ASSERT_FALSE(outcomes[0].hasValue());
    EXPECT_EQ(outcomes[0].error().kind, StreamErrorKind::Interrupted);
    EXPECT_EQ(outcomes[0].error().message,
              "broadcast stream (hash 0x0300): a frame with DLC 5 arrived after 16 "
              "of 95 bytes; reception aborted, the bytes are dropped");
    EXPECT_EQ(outcomes.size(), 1u); // the remaining data frames are dropped quietly
}

TEST(ConfigStreamReceiver, FrameOfAnotherLengthOutsideAStreamIsIgnored) {
    ConfigStreamReceiver receiver;
    EXPECT_TRUE(receiver.feed(frame("00420300 5 01 02 03 04 05")).empty());
    EXPECT_TRUE(receiver.feed(frame("00004711 5 00 00 00 00 01")).empty()); // not a stream frame
}

TEST(ConfigStreamReceiver, InputEndingInsideAStreamIsIncomplete) {
    auto frames = corpusStream();
    frames.resize(7);
    const auto error = singleError(receiveAll(frames));
    EXPECT_EQ(error.kind, StreamErrorKind::Incomplete);
    EXPECT_EQ(error.message, "broadcast stream (hash 0x0300): the input ended after 48 of 95 bytes");
}

TEST(ConfigStreamReceiver, DataOfAnotherHashDoesNotDisturbTheStream) {
    auto frames = corpusStream();
    frames.insert(frames.begin() + 2, dataFrame(0x4711, {1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(singleFile(receiveAll(frames)).contents.size(), 170u);
}

// ---- Progress -----------------------------------------------------------------------------------

TEST(ConfigStreamReceiver, ProgressIsReportedFrameByFrame) {
    ConfigStreamReceiver receiver;
    std::vector<std::size_t> received;
    receiver.onProgress([&](const StreamProgress& p) {
        EXPECT_EQ(p.announced, 95u);
        EXPECT_EQ(p.hash, 0x0300);
        received.push_back(p.received);
    });
    const auto frames = corpusStream();
    for (std::size_t i = 0; i < 5; ++i)
        receiver.feed(frames[i]);
    EXPECT_TRUE(receiver.collecting());
    EXPECT_EQ(receiver.progress().received, 32u);
    EXPECT_TRUE(receiver.progress().active);
    for (std::size_t i = 5; i < frames.size(); ++i)
        receiver.feed(frames[i]);
    EXPECT_EQ(received, (std::vector<std::size_t>{0, 8, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 95}));
    EXPECT_FALSE(receiver.collecting());
    EXPECT_FALSE(receiver.progress().active);
    EXPECT_EQ(receiver.progress().received, 95u);
}

// ---- Across the layers: the streamed page is a track plan page ----------------------------------

TEST(ConfigStreamReceiver, CorpusLogPageReadsAsATrackPageWithThreeStraights) {
    const auto file = singleFile(receiveAll(corpusStream()));
    Diagnostics diagnostics("gbs stream");
    const TrackPage page = TrackPage::read(Document::parse(file.contents, diagnostics), diagnostics);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    ASSERT_EQ(page.elements.size(), 3u);
    for (const TrackElement& element : page.elements)
        EXPECT_EQ(element.type, "gerade");
    EXPECT_EQ(page.write().serialize(), file.contents);
}
