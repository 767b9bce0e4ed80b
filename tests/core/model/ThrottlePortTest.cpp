// Issue 35: one throttle port for every kind of throttle. It reads a locomotive's state as the station
// confirmed it, drives it with the desk's commands, and its owner book names one driver per locomotive
// across every kind, the last to drive taking it over and the one before told.

#include "model/ThrottlePort.h"

#include "ModelBench.h"

namespace stellwerk::model::test {
namespace {

class ThrottlePortTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(bench.start()); }

    ThrottlePort& port() { return bench.railway.throttlePort(); }

    ModelBench bench;
};

TEST(LocoOwnersTest, TheLastThrottleToDriveTakesTheLocoOverAndTheOneBeforeIsTold) {
    LocoOwners owners;
    QSignalSpy taken(&owners, &LocoOwners::takenOver);
    EXPECT_EQ(owners.take(Br86, QStringLiteral("z21:a")), QString());
    EXPECT_EQ(owners.take(Br86, QStringLiteral("z21:a")), QString()) << "the same throttle again";
    EXPECT_EQ(taken.count(), 0);
    EXPECT_EQ(owners.take(Br86, QStringLiteral("ms1")), QStringLiteral("z21:a"));
    ASSERT_EQ(taken.count(), 1);
    EXPECT_EQ(taken.at(0).at(1).toString(), QStringLiteral("z21:a"));
    EXPECT_EQ(taken.at(0).at(2).toString(), QStringLiteral("ms1"));
    EXPECT_EQ(owners.driverOf(Br86), QStringLiteral("ms1"));
    EXPECT_TRUE(owners.drivenBy(QStringLiteral("z21:a")).isEmpty());
}

TEST(LocoOwnersTest, ReleaseAllLetsGoOfOnlyTheThrottlesOwnLocos) {
    LocoOwners owners;
    owners.take(Br86, QStringLiteral("a"));
    owners.take(V100, QStringLiteral("a"));
    owners.take(V100, QStringLiteral("b"));
    owners.release(V100, QStringLiteral("a"));
    EXPECT_EQ(owners.driverOf(V100), QStringLiteral("b"))
        << "a release by a throttle that lost it is ignored";
    EXPECT_EQ(owners.releaseAll(QStringLiteral("a")), QList<quint32>{Br86});
    EXPECT_EQ(owners.driverOf(Br86), QString());
    EXPECT_EQ(owners.driverOf(V100), QStringLiteral("b"));
}

TEST_F(ThrottlePortTest, DrivingNamesTheDriverAndConfirmedFollowsTheStation) {
    port().setSpeed(QStringLiteral("z21:a"), Br86, 400);
    EXPECT_EQ(port().owners().driverOf(Br86), QStringLiteral("z21:a"));
    ASSERT_TRUE(waitFor([&] { return port().confirmed(Br86) && port().confirmed(Br86)->speed == 400; }));
    EXPECT_EQ(bench.station.loco(Br86)->speed, 400);
    port().setFunction(QStringLiteral("orc"), Br86, 1, true);
    ASSERT_TRUE(waitFor([&] { return port().confirmed(Br86)->functions == 0b10u; }));
    EXPECT_EQ(port().owners().driverOf(Br86), QStringLiteral("orc"));
}

TEST_F(ThrottlePortTest, AThrottleThatGoesAwayHasItsLocosStopped) {
    port().setSpeed(QStringLiteral("z21:a"), Br86, 400);
    port().setSpeed(QStringLiteral("z21:b"), V100, 300);
    ASSERT_TRUE(waitFor([&] { return bench.station.loco(Br86)->speed == 400; }));
    EXPECT_EQ(port().stopDrivenBy(QStringLiteral("z21:a")), QList<quint32>{Br86});
    ASSERT_TRUE(waitFor([&] { return bench.station.loco(Br86)->speed == 0; }));
    EXPECT_EQ(bench.station.loco(V100)->speed, 300) << "another throttle's loco runs on";
}

TEST_F(ThrottlePortTest, NothingIsConfirmedWhileTheStationIsNotHeard) {
    port().setSpeed(QStringLiteral("z21:a"), Br86, 400);
    ASSERT_TRUE(waitFor([&] { return port().confirmed(Br86) && port().confirmed(Br86)->speed == 400; }));
    bench.stationEnd.close();
    EXPECT_FALSE(port().canDrive());
    EXPECT_FALSE(port().confirmed(Br86).has_value());
    ASSERT_TRUE(port().shown(Br86).has_value());
    EXPECT_EQ(port().shown(Br86)->speed, 400);
    EXPECT_FALSE(port().powerOn().has_value());
}

} // namespace
} // namespace stellwerk::model::test
