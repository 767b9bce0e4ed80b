#include "ConfigTestSupport.h"
#include "cs2config/TrackPage.h"
#include "cs2config/TrackPlan.h"
#include "cs2config/TrackStatus.h"

#include <gtest/gtest.h>
#include <random>
#include <tuple>

using namespace stellwerk::cs2config;
using namespace stellwerk::cs2config::test;

namespace {

constexpr int iterations = 2000;

// Damages a file a few times: changed, inserted, deleted and copied bytes, a cut, a stray line.
std::string mutateTrack(std::string bytes, std::mt19937& random) {
    static constexpr std::string_view pieces = "\n\r .=[]0x-9aZ\t\xff\xc3";
    static constexpr std::string_view lines[] = {"element\n", " .id=0x\n", " .typ=\n",
                                                 " ..x=1\n",  "[conf]\n",  " .drehung=9\n",
                                                 "seite\n",   " .name\n",  "version\n"};
    const auto pick = [&random](std::size_t size) { return size == 0 ? 0 : random() % size; };
    const unsigned edits = 1 + random() % 6;
    for (unsigned i = 0; i < edits; ++i) {
        const std::size_t at = pick(bytes.size());
        switch (random() % 6) {
        case 0:
            if (!bytes.empty())
                bytes[at] = static_cast<char>(random());
            break;
        case 1:
            bytes.insert(at, 1, pieces[pick(pieces.size())]);
            break;
        case 2:
            bytes.erase(at, 1 + random() % 8);
            break;
        case 3:
            bytes.insert(at, bytes.substr(pick(bytes.size()), random() % 64));
            break;
        case 4:
            if (random() % 8 == 0)
                bytes.resize(at);
            break;
        default:
            bytes.insert(at, lines[pick(std::size(lines))]);
            break;
        }
    }
    return bytes;
}

auto typed(const TrackElement& e) {
    return std::make_tuple(e.position.toId(), e.type, e.rotation, e.article, e.text, e.deviceId, e.state);
}

// Every element changed at once must read back as changed, whatever the file looked like.
void expectEditsSurvive(const TrackPage& read) {
    TrackPage edited = read;
    for (TrackElement& element : edited.elements) {
        element.position.column = static_cast<std::uint8_t>(element.position.column + 1);
        element.rotation = (element.rotation + 1) % 4;
        element.text += "x";
        element.state += 1;
    }
    Diagnostics diagnostics;
    const TrackPage reread =
        TrackPage::read(Document::parse(edited.write().serialize(), diagnostics), diagnostics);
    ASSERT_EQ(reread.elements.size(), edited.elements.size());
    for (std::size_t i = 0; i < reread.elements.size(); ++i)
        ASSERT_EQ(typed(reread.elements[i]), typed(edited.elements[i])) << "element " << i;
}

template <class Model>
void fuzz(const std::string& original, unsigned seed, void (*check)(const Model&) = nullptr) {
    std::mt19937 random(seed);
    for (int i = 0; i < iterations; ++i) {
        const std::string bytes = mutateTrack(original, random);
        Diagnostics diagnostics;
        const Document document = Document::parse(bytes, diagnostics);
        ASSERT_EQ(document.serialize(), bytes) << "iteration " << i;
        const Model model = Model::read(document, diagnostics);
        ASSERT_EQ(model.write().serialize(), bytes) << "iteration " << i;
        EXPECT_FALSE(toJson(model).empty());
        if (check)
            check(model);
        if (testing::Test::HasFatalFailure())
            FAIL() << "iteration " << i << ", input:\n" << bytes;
    }
}

std::string trackStatusFile() {
    std::string text = "[gleisbild]\nversion\n .major=0\n .minor=1\n";
    for (int id = 0x101; id < 0x140; ++id)
        text += "element\n .id=" + std::to_string(id) + "\n" +
                (id % 3 ? " .zustand=" + std::to_string(id % 4) + "\n" : "");
    return text;
}

} // namespace

TEST(TrackFuzz, PagesSurviveDamagedBytes) {
    fuzz<TrackPage>(readCorpus(corpus::testPage), 1, expectEditsSurvive);
    fuzz<TrackPage>(readCorpus(corpus::karben), 2, expectEditsSurvive);
}

TEST(TrackFuzz, IndexSurvivesDamagedBytes) {
    fuzz<TrackPlan>(
        readCorpus(corpus::gleisbildMrFlexi), 3, +[](const TrackPlan& read) {
            TrackPlan edited = read;
            for (TrackPageEntry& page : edited.pages) {
                page.id += 1;
                page.name += " 2";
            }
            Diagnostics diagnostics;
            const TrackPlan reread =
                TrackPlan::read(Document::parse(edited.write().serialize(), diagnostics), diagnostics);
            ASSERT_EQ(reread.pages.size(), edited.pages.size());
            for (std::size_t i = 0; i < reread.pages.size(); ++i) {
                EXPECT_EQ(reread.pages[i].id, edited.pages[i].id);
                EXPECT_EQ(reread.pages[i].name, edited.pages[i].name);
            }
        });
}

TEST(TrackFuzz, StatusFileSurvivesDamagedBytes) {
    fuzz<TrackStatusFile>(trackStatusFile(), 4);
}
