// After the start-up the railway holds the station's layout: locomotives with their functions,
// accessories, routes, track plan pages and devices with their gauges.

#include "ModelBench.h"

namespace stellwerk::model::test {
namespace {

TEST(RailwayStartup, HoldsTheLocomotivesAccessoriesRoutesPagesAndDevicesOfTheStation) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    const Railway& railway = bench.railway;

    ASSERT_EQ(railway.state().locomotives().size(), 2u);
    const Locomotive* br86 = railway.locomotive(Br86);
    ASSERT_NE(br86, nullptr);
    EXPECT_EQ(br86->name(), "BR 86");
    EXPECT_EQ(br86->decoder(), cs2config::LocomotiveDecoder::Mfx);
    ASSERT_EQ(br86->functions().size(), 2u);
    EXPECT_EQ(br86->function(1)->icon, 23);
    EXPECT_EQ(br86->function(1)->trigger, cs2config::FunctionTrigger::Momentary);

    ASSERT_EQ(railway.state().accessories().keys(), (std::vector<std::int64_t>{1, 2, 5}));
    EXPECT_EQ(railway.accessory(2)->addressCount(), 2);
    EXPECT_EQ(railway.accessory(2)->positionCount(), 3);
    EXPECT_EQ(railway.accessory(5)->name(), "S5");

    ASSERT_EQ(railway.state().routes().size(), 4u);
    EXPECT_EQ(railway.route(1)->name(), "Einfahrt");
    EXPECT_EQ(railway.route(1)->steps().size(), 3u);

    ASSERT_EQ(railway.layout().pages().size(), 1u);
    const LayoutPage& page = railway.layout().pages()[0];
    EXPECT_EQ(page.name, "Bahnhof");
    ASSERT_EQ(page.tiles.size(), 3u);
    EXPECT_EQ(page.tiles[0].contact, contactKey(0, 7));
    EXPECT_EQ(page.tiles[1].accessory, 1) << "field notes: .artikel = 2 x the article's id";
    EXPECT_EQ(page.tiles[2].route, 1);
    ASSERT_NE(railway.contact(contactKey(0, 7)), nullptr);
    EXPECT_EQ(railway.contact(contactKey(0, 7))->name(), "Gleis 1");

    const Device* cs2 = railway.device(CentralStationUid);
    ASSERT_NE(cs2, nullptr);
    EXPECT_TRUE(cs2->described());
    ASSERT_EQ(cs2->channels().size(), 4u);
    EXPECT_EQ(cs2->channels()[2].name(), "VOLT");
    EXPECT_EQ(cs2->channels()[2].unit(), "V");
}

// Field notes: the station does not tell a late joiner; the start-up asks, and a railway created before
// the start-up keeps the answers.
TEST(RailwayStartup, KeepsTheStatesTheStartupAskedFor) {
    ModelBench bench;
    bench.station.setContact(0, 7, true);
    ASSERT_TRUE(bench.start());
    const FeedbackContact* contact = bench.railway.contact(contactKey(0, 7));
    ASSERT_NE(contact, nullptr);
    EXPECT_TRUE(contact->known());
    EXPECT_TRUE(contact->occupied());
    EXPECT_EQ(contact->name(), "Gleis 1") << "the page's name is kept with the state";
    const Locomotive* br86 = bench.railway.locomotive(Br86);
    ASSERT_NE(br86, nullptr);
    EXPECT_EQ(br86->name(), "BR 86");
    EXPECT_EQ(br86->direction(), cs2::Direction::Forward);
}

TEST(RailwayStartup, LoadsTheDemoLayout) {
    sim::StationLayout demo = sim::StationLayout::demo();
    if (demo.locomotives().locomotives.empty())
        GTEST_SKIP() << "the demo layout is not built in";
    const std::size_t locomotives = demo.locomotives().locomotives.size();
    const std::size_t pages = demo.trackPlan().pages.size();
    ModelBench bench(std::move(demo));
    ASSERT_TRUE(bench.start());
    EXPECT_EQ(bench.railway.state().locomotives().size(), locomotives);
    EXPECT_EQ(bench.railway.layout().pages().size(), pages);
    EXPECT_FALSE(bench.railway.state().routes().items().empty());
    EXPECT_FALSE(bench.railway.state().contacts().items().empty());
}

} // namespace
} // namespace stellwerk::model::test
