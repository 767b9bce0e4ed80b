// Document 4.1: switching accessories through the railway; the position shown is the one the station
// confirmed, on every tile that shows the accessory.

#include "ModelBench.h"

namespace stellwerk::model::test {
namespace {

class AccessoryIntents : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(bench.start()); }

    ModelBench bench;
};

// Field notes: keyboard numbers are 1-based; MM accessory 1 is Loc-ID 0x3000.
TEST_F(AccessoryIntents, SwitchAccessoryShowsTheConfirmedPosition) {
    QSignalSpy changed(&bench.railway, &Railway::accessoriesChanged);
    QSignalSpy tiles(&bench.railway, &Railway::tilesChanged);
    bench.railway.switchAccessory(1, 1);
    ASSERT_TRUE(waitFor([&] { return bench.railway.accessory(1)->position() == 1; }));
    EXPECT_EQ(bench.station.accessoryPosition(0x3000), 1);
    ASSERT_EQ(changed.count(), 1);
    EXPECT_EQ(changed.first().at(0).value<QList<qint64>>(), QList<qint64>{1});
    ASSERT_EQ(tiles.count(), 1);
    const auto refs = tiles.first().at(0).value<QList<TileRef>>();
    ASSERT_EQ(refs.size(), 1);
    EXPECT_EQ(bench.railway.layout().tile(refs[0]).text, "W1");
}

// A three-way turnout has two addresses: positions 2 and 3 are on the second one.
TEST_F(AccessoryIntents, AThreeWayTurnoutsThirdPositionIsOnItsSecondAddress) {
    bench.railway.switchAccessory(2, 2);
    ASSERT_TRUE(waitFor([&] { return bench.railway.accessory(2)->position() == 2; }));
    EXPECT_EQ(bench.station.accessoryPosition(0x3002), 0) << "address 3, output 0";
    bench.railway.switchAccessory(2, 1);
    ASSERT_TRUE(waitFor([&] { return bench.railway.accessory(2)->position() == 1; }));
    EXPECT_EQ(bench.station.accessoryPosition(0x3001), 1);
}

TEST_F(AccessoryIntents, APositionTheArticleDoesNotHaveIsAProblem) {
    QSignalSpy problems(&bench.railway, &Railway::problem);
    bench.railway.switchAccessory(1, 3);
    bench.railway.switchAccessory(42, 0);
    ASSERT_EQ(problems.count(), 2);
    EXPECT_TRUE(problems.at(0).at(0).toString().contains("W1"))
        << problems.at(0).at(0).toString().toStdString();
    EXPECT_TRUE(problems.at(1).at(0).toString().contains("42"));
}

TEST(Accessory, MapsPositionsOntoItsAddresses) {
    cs2config::Accessory record;
    record.id = 7;
    record.type = "dreiwegweiche";
    record.protocol = "dcc";
    const Accessory threeWay = Accessory::fromFile(record);
    ASSERT_EQ(threeWay.addressCount(), 2);
    EXPECT_EQ(threeWay.outputFor(0)->address.value(), 0x3806u);
    EXPECT_EQ(threeWay.outputFor(2)->address.value(), 0x3807u);
    EXPECT_EQ(threeWay.outputFor(2)->output, 0);
    EXPECT_FALSE(threeWay.outputFor(3)) << "a three-way turnout has three positions";
    EXPECT_EQ(threeWay.positionOf(1, 0), 2);
}

} // namespace
} // namespace stellwerk::model::test
