// The real stellwerk-sim with --ro N: the options are listed and checked, and Stellwerk's session switches
// a relay of its second module over the station's TCP port (29-bit frames in the 13-byte network form),
// which the simulator prints.
#include "EventLoopWait.h"
#include "SimProgram.h"
#include "bus/Bus.h"
#include "romodule/RoModuleSession.h"
#include "transport/TcpTransport.h"

#include <gtest/gtest.h>

namespace stellwerk::romodule::test {
namespace {

using support::Quiet;
using support::SimProgram;

TEST(SimProgramRo, HelpListsTheRoOptionsAndBadValuesAreRefused) {
    SimProgram help({"--help"});
    EXPECT_EQ(help.exitCode(), 0);
    EXPECT_TRUE(help.output().contains("--ro <N>")) << help.output().toStdString();
    EXPECT_TRUE(help.output().contains("--ro-lose-every <N>"));
    EXPECT_TRUE(help.output().contains("--ro-delay <ms>"));
    SimProgram tooMany({"--ro", "65"});
    EXPECT_EQ(tooMany.exitCode(), 2);
    EXPECT_TRUE(tooMany.output().contains("--ro: '65' is not 0..64")) << tooMany.output().toStdString();
}

TEST(SimProgramRo, ARelayOfTheSecondModuleSwitchedOverTcp) {
    SimProgram sim(QStringList{"--ro", "2", "--ro-lose-every", "3"} + Quiet);
    const std::uint16_t port = sim.tcpPort();
    ASSERT_NE(port, 0) << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("RO modules: 2 on the bus"));

    transport::TcpTransport wire(transport::TcpSettings{QStringLiteral("127.0.0.1"), port, {}});
    const ro::RoProfile module = ro::RoProfile::simulator(2);
    busreading::BusProfile profile = busreading::BusProfile::centralStation();
    profile.addRoModule(ro::RoProfile::simulator(1).ids).addRoModule(module.ids);
    bus::Bus bus(wire, profile, QStringLiteral("CS2"));
    SessionTiming timing;
    timing.answerTimeout = std::chrono::milliseconds(200); // a process and a TCP hop away
    RoModuleSession session(bus, module, timing);
    wire.open();
    ASSERT_TRUE(support::runEventsUntil(
        [&] { return wire.state() == transport::Transport::State::Connected; }, 5000));
    session.start();
    ASSERT_TRUE(support::runEventsUntil([&] { return session.outputs().has_value(); }, 5000));
    ASSERT_TRUE(session.setOutput(3, true));
    ASSERT_TRUE(support::runEventsUntil([&] { return session.outputs() == 0x0004u; }, 5000));
    EXPECT_TRUE(sim.printed("RO module 2: relays 0000000000000100")) << sim.output().toStdString();
    EXPECT_FALSE(sim.output().contains("RO module 1: relays")) << "module 1 was not asked";
    EXPECT_EQ(sim.output().count("RO module 2: relays"), 1)
        << "switched once, though every 3rd answer is lost";
}

} // namespace
} // namespace stellwerk::romodule::test
