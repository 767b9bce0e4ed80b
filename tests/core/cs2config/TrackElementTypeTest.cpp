#include "cs2config/TrackElementType.h"

#include "ConfigTestSupport.h"
#include "cs2config/TrackPage.h"

#include <gtest/gtest.h>
#include <set>
#include <sstream>

using namespace stellwerk::cs2config;
using namespace stellwerk::cs2config::test;

namespace {

// Document 8.3.5, "Typ des Elements. Mögliche Werte", word for word ("drehscheibe_dig_0 .. bis
// drehscheibe_dig_31" written out).
std::vector<std::string> documentedTypes() {
    std::istringstream words(
        "leer gerade kreuzung unterfuehrung prellbock bogen doppelbogen tunnel linksweiche rechtsweiche "
        "dreiwegweiche yweiche dkweiche dkweiche_2 signal s88kontakt s88bogen pfeil fahrstrasse text "
        "signal_hp02 "
        "signal_hp012 signal_hp01s signal_p_hp012s signal_f_hp012s signal_p_hp012 signal_f_hp01 "
        "signal_f_hp02 "
        "signal_f_hp012 signal_sh01 k84_einfach k84_doppelt entkuppler entkuppler_1 std_rot std_gruen "
        "std_rot_gruen_0 std_rot_gruen_1 schiebebuehne_0 schiebebuehne_1 schiebebuehne_2 schiebebuehne_3 "
        "drehscheibe_alt_0 drehscheibe_alt_1 drehscheibe_alt_2 drehscheibe_alt_3");
    std::vector<std::string> types;
    for (std::string word; words >> word;)
        types.push_back(word);
    for (int i = 0; i <= 31; ++i)
        types.push_back("drehscheibe_dig_" + std::to_string(i));
    return types;
}

const TrackElementType& type(std::string_view name) {
    const TrackElementType* found = findTrackElementType(name);
    EXPECT_NE(found, nullptr) << name;
    static const TrackElementType none{"", TrackCategory::Unknown, ArticleLink::None, false};
    return found ? *found : none;
}

} // namespace

TEST(TrackElementType, EveryDocumentedTypeIsKnown) {
    const std::vector<std::string> documented = documentedTypes();
    EXPECT_EQ(documented.size(), 78u);
    for (const std::string& name : documented) {
        const TrackElementType& known = type(name);
        EXPECT_TRUE(known.documented) << name;
        EXPECT_NE(known.category, TrackCategory::Unknown) << name;
    }
    const auto isDocumented = [](const TrackElementType& t) { return t.documented; };
    EXPECT_EQ(std::count_if(trackElementTypes().begin(), trackElementTypes().end(), isDocumented), 78);
}

TEST(TrackElementType, NamesAreUnique) {
    std::set<std::string_view> names;
    for (const TrackElementType& known : trackElementTypes())
        EXPECT_TRUE(names.insert(known.name).second) << known.name;
}

TEST(TrackElementType, CategoriesForRendererAndTurnoutPanel) {
    EXPECT_EQ(type("leer").category, TrackCategory::Empty);
    EXPECT_EQ(type("gerade").category, TrackCategory::Track);
    EXPECT_EQ(type("doppelbogen").category, TrackCategory::Track);
    EXPECT_EQ(type("prellbock").category, TrackCategory::Track);
    EXPECT_EQ(type("linksweiche").category, TrackCategory::Turnout);
    EXPECT_EQ(type("dkweiche_2").category, TrackCategory::Turnout);
    EXPECT_EQ(type("signal_f_hp012").category, TrackCategory::Signal);
    EXPECT_EQ(type("s88bogen").category, TrackCategory::Feedback);
    EXPECT_EQ(type("fahrstrasse").category, TrackCategory::RouteButton);
    EXPECT_EQ(type("pfeil").category, TrackCategory::PageLink);
    EXPECT_EQ(type("text").category, TrackCategory::Text);
    EXPECT_EQ(type("entkuppler_1").category, TrackCategory::Uncoupler);
    EXPECT_EQ(type("std_rot_gruen_1").category, TrackCategory::Output);
    EXPECT_EQ(type("k84_doppelt").category, TrackCategory::Output);
    EXPECT_EQ(type("drehscheibe_dig_31").category, TrackCategory::Turntable);
    EXPECT_EQ(type("drehscheibe_alt_2").category, TrackCategory::Turntable);
    EXPECT_EQ(type("schiebebuehne_3").category, TrackCategory::TransferTable);
}

TEST(TrackElementType, SwitchableMeansLinkedToAnAccessory) {
    EXPECT_FALSE(type("gerade").switchable());
    EXPECT_EQ(type("gerade").article, ArticleLink::None);
    EXPECT_TRUE(type("rechtsweiche").switchable());
    EXPECT_TRUE(type("signal_p_hp012s").switchable());
    EXPECT_TRUE(type("entkuppler").switchable());
    EXPECT_TRUE(type("std_gruen").switchable());
    EXPECT_TRUE(type("drehscheibe_dig_0").switchable());
    EXPECT_FALSE(type("s88kontakt").switchable());
    EXPECT_EQ(type("s88kontakt").article, ArticleLink::FeedbackContact);
    EXPECT_FALSE(type("fahrstrasse").switchable());
    EXPECT_EQ(type("fahrstrasse").article, ArticleLink::Route);
    EXPECT_EQ(type("pfeil").article, ArticleLink::Page);
    EXPECT_FALSE(type("text").switchable());
}

TEST(TrackElementType, FirmwareTypesBeyondTheDocument) {
    for (const char* name : {"s88doppelbogen", "signal_hp012s", "drehscheibe", "lampe", "hosentraeger"}) {
        EXPECT_FALSE(type(name).documented) << name;
        EXPECT_NE(type(name).category, TrackCategory::Unknown) << name;
    }
    EXPECT_EQ(type("s88doppelbogen").category, TrackCategory::Feedback);
    EXPECT_EQ(type("hosentraeger").category, TrackCategory::Turnout);
    EXPECT_EQ(type("drehscheibe").category, TrackCategory::Turntable);
    EXPECT_EQ(type("lampe").category, TrackCategory::Output);
}

TEST(TrackElementType, UnknownWords) {
    EXPECT_EQ(findTrackElementType("custom_perm_left"), nullptr);
    EXPECT_EQ(findTrackElementType(""), nullptr);
    EXPECT_EQ(findTrackElementType("Gerade"), nullptr);
    EXPECT_EQ(trackCategoryName(TrackCategory::Unknown), "unknown");
    EXPECT_EQ(trackCategoryName(TrackCategory::RouteButton), "route button");
}

// Every `.typ` of every corpus page is known, except TrainControl's own extension types in "5 - Test".
TEST(TrackElementType, EveryTypeInTheCorpusPages) {
    std::set<std::string> unknown;
    std::set<std::string> seen;
    for (const std::string_view file : {corpus::karben, corpus::gbs0, corpus::testPage}) {
        Parsed parsed = parseCorpus(file);
        const TrackPage page = TrackPage::read(parsed.document, parsed.diagnostics);
        for (const TrackElement& element : page.elements) {
            seen.insert(element.type);
            if (!element.elementType())
                unknown.insert(element.type);
        }
    }
    EXPECT_EQ(seen.size(), 22u); // 21 words and the empty type of a text-only element
    EXPECT_EQ(unknown, (std::set<std::string>{"custom_perm_left", "custom_perm_right", "custom_perm_y"}));
}
