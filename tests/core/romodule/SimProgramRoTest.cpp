// The real stellwerk-sim with --ro N: the options are listed and checked, and Stellwerk's session switches
// a relay of its second module over the station's TCP port (29-bit frames in the 13-byte network form),
// which the simulator prints.
#include "EventLoopWait.h"
#include "buses/Bus.h"
#include "romodule/RoModuleSession.h"
#include "transport/TcpTransport.h"

#include <QProcess>
#include <QRegularExpression>
#include <gtest/gtest.h>

namespace stellwerk::romodule::test {
namespace {

// stellwerk-sim on free loopback ports, without trains; its output collected.
class SimProgram {
public:
    explicit SimProgram(const QStringList& arguments) {
        process_.setProcessChannelMode(QProcess::MergedChannels);
        process_.start(QStringLiteral(STELLWERK_SIM), arguments);
    }
    ~SimProgram() {
        if (process_.state() != QProcess::NotRunning) {
            process_.terminate();
            process_.waitForFinished(5000);
        }
    }
    QString output() {
        out_ += QString::fromUtf8(process_.readAll());
        return out_;
    }
    bool printed(const QString& text) {
        return support::runEventsUntil([&] { return output().contains(text); }, 15000);
    }
    int exitCode() {
        process_.waitForFinished(5000);
        output();
        return process_.exitCode();
    }
    std::uint16_t tcpPort() {
        const QRegularExpression listening(QStringLiteral("listening: tcp 127\\.0\\.0\\.1:(\\d+)"));
        QRegularExpressionMatch match;
        support::runEventsUntil([&] { return (match = listening.match(output())).hasMatch(); }, 15000);
        return match.hasMatch() ? std::uint16_t(match.captured(1).toUInt()) : 0;
    }

private:
    QProcess process_;
    QString out_;
};

const QStringList Quiet = {"--listen",   "127.0.0.1", "--udp-port",  "0", "--udp-reply-host", "127.0.0.1",
                           "--tcp-port", "0",         "--http-port", "0", "--no-trains"};

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
    bus::BusProfile profile = bus::BusProfile::centralStation();
    profile.addRoModule(ro::RoProfile::simulator(1).ids).addRoModule(module.ids);
    buses::Bus bus(wire, profile, QStringLiteral("CS2"));
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
