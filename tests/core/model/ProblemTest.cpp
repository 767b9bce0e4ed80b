// Document 1.2.5: a command without acknowledgement must be assumed not carried out. The railway says
// so in a sentence a person can act on, and shows nothing that was not confirmed.

#include "ModelBench.h"
#include "model/CommandProblem.h"

namespace stellwerk::model::test {
namespace {

TEST(Problems, ACommandTheStationDoesNotAnswerBecomesAProblem) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    QSignalSpy problems(&bench.railway, &Railway::problem);
    bench.deaf = true;
    bench.railway.setSpeed(Br86, 300);
    ASSERT_TRUE(waitFor([&] { return problems.count() == 1; }));
    const QString message = problems.first().at(0).toString();
    EXPECT_TRUE(message.startsWith("BR 86: speed 300 was not carried out")) << message.toStdString();
    EXPECT_TRUE(message.contains("no answer from the station after 2 attempts")) << message.toStdString();
    EXPECT_EQ(bench.railway.locomotive(Br86)->speed(), 0);
}

TEST(Problems, ARejectedCommandSaysTheStationRefusedIt) {
    station::CommandResult result;
    result.status = station::CommandResult::Status::Rejected;
    EXPECT_EQ(commandProblem("W1: position 1", result),
              "W1: position 1 was not carried out: the station refused it");
}

TEST(Problems, StopAndGoShowTheConfirmedTrackPower) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    QSignalSpy power(&bench.railway, &Railway::powerChanged);
    bench.railway.go();
    ASSERT_TRUE(waitFor([&] { return bench.railway.power() == station::PowerState::Running; }));
    bench.railway.stop();
    ASSERT_TRUE(waitFor([&] { return bench.railway.power() == station::PowerState::Stopped; }));
    EXPECT_EQ(bench.station.power(), sim::SimulatedStation::Power::Stopped);
    EXPECT_EQ(power.count(), 2);
}

} // namespace
} // namespace stellwerk::model::test
