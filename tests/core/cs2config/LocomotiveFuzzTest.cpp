// Damaged and random input: the readers return, and writing what they read gives back the bytes.
#include "ConfigTestSupport.h"
#include "cs2config/LocomotiveFile.h"
#include "cs2config/LocomotiveStateFile.h"
#include "cs2config/Ms2LocoDatabaseVersion.h"
#include "cs2config/Ms2LocoInfo.h"
#include "cs2config/Ms2LocoNames.h"

#include <array>
#include <gtest/gtest.h>
#include <random>
#include <string>

namespace stellwerk::cs2config::test {
namespace {

// Bytes that matter to the format, so that mutations make lines, blocks and values.
constexpr std::string_view interesting = "\n\r.= .0x-1#\t[]lokomotive";

// The text with a few random changes: bytes replaced, inserted or removed, a line cut short.
std::string mutate(std::string text, std::mt19937& random) {
    std::uniform_int_distribution<int> edits(1, 8);
    const int count = edits(random);
    for (int i = 0; i < count && !text.empty(); ++i) {
        std::uniform_int_distribution<std::size_t> position(0, text.size() - 1);
        std::uniform_int_distribution<int> byte(0, 255);
        std::uniform_int_distribution<std::size_t> pick(0, interesting.size() - 1);
        const std::size_t at = position(random);
        switch (random() % 5) {
        case 0:
            text[at] = static_cast<char>(byte(random));
            break;
        case 1:
            text[at] = interesting[pick(random)];
            break;
        case 2:
            text.insert(at, 1, interesting[pick(random)]);
            break;
        case 3:
            text.erase(at, std::min<std::size_t>(text.size() - at, 1 + random() % 40));
            break;
        default:
            text.resize(at);
            break;
        }
    }
    return text;
}

// Reads the bytes with a model and checks that writing the unchanged model gives them back.
template <class Model>
void expectRoundTrip(const std::string& bytes, int iteration) {
    Diagnostics diagnostics;
    const Document document = Document::parse(bytes, diagnostics);
    ASSERT_EQ(document.serialize(), bytes) << "iteration " << iteration;
    const Model model = Model::read(document, diagnostics);
    ASSERT_EQ(model.write().serialize(), bytes) << "iteration " << iteration;
}

TEST(LocomotiveFuzz, MutatedCorpusFilesReadAndWriteBackUnchanged) {
    const std::array<std::string, 5> sources{
        readCorpus(corpus::lokomotiveGbert), readCorpus(corpus::lokomotiveSrseii),
        readCorpus(corpus::lokomotiveCorrupted), readCorpus(corpus::cs3Loco),
        readCorpus(corpus::lokomotiveTrainControl).substr(0, 12000)};
    std::mt19937 random(20240611);
    for (int iteration = 0; iteration < 2000; ++iteration) {
        const std::string bytes =
            mutate(sources[static_cast<std::size_t>(iteration) % sources.size()], random);
        expectRoundTrip<LocomotiveFile>(bytes, iteration);
        if (HasFatalFailure())
            return;
    }
}

TEST(LocomotiveFuzz, RandomBytesAreReadWithoutHarm) {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int iteration = 0; iteration < 300; ++iteration) {
        std::string bytes(random() % 2000, '\0');
        for (char& c : bytes)
            c = random() % 3 == 0 ? interesting[random() % interesting.size()]
                                  : static_cast<char>(byte(random));
        expectRoundTrip<LocomotiveFile>(bytes, iteration);
        expectRoundTrip<LocomotiveStateFile>(bytes, iteration);
        expectRoundTrip<Ms2LocoInfo>(bytes, iteration);
        expectRoundTrip<Ms2LocoNames>(bytes, iteration);
        expectRoundTrip<Ms2LocoDatabaseVersion>(bytes, iteration);
        if (HasFatalFailure())
            return;
    }
}

TEST(LocomotiveFuzz, MutatedStreamsReadAndWriteBackUnchanged) {
    const std::string lokinfo = "[lokomotive]\nlok\n  .uid=0x4005\n  .name=M4\n  .adresse=0x9\n  .typ=mfx\n"
                                "  .mfxuid=0xff001234\n  .av=64\n  .fkt\n  ..nr=0\n  ..typ=32\n  .mfxAdr\n"
                                "  ..target=2\n  ..name=3\n  ..addr=136\n";
    const std::string loknamen = "[lokomotive]\nlok\n  .nr=3\n  .name=MaK 1206 ACTS\nlok\n  .nr=4\n"
                                 "  .name=M4-RIOs\nnumloks\n  .wert=8\n";
    const std::string ldbver = ".version=9  \n.monat=2  \n.jahr=10  \n.anzahl=1078";
    const std::string status = "[lokomotive]\nversion\n .major=0\n .minor=1\nlokomotive\n .name=BR 86\n"
                               " .velocity=250\n .richtung=1\n .funktionen\n ..nr=0\n ..wert=1\n";
    std::mt19937 random(99);
    for (int iteration = 0; iteration < 500; ++iteration) {
        expectRoundTrip<Ms2LocoInfo>(mutate(lokinfo, random), iteration);
        expectRoundTrip<Ms2LocoNames>(mutate(loknamen, random), iteration);
        expectRoundTrip<Ms2LocoDatabaseVersion>(mutate(ldbver, random), iteration);
        expectRoundTrip<LocomotiveStateFile>(mutate(status, random), iteration);
        if (HasFatalFailure())
            return;
    }
}

} // namespace
} // namespace stellwerk::cs2config::test
