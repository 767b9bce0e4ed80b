// The two programs together: stellwerk-sim with --orc-booster, --orc-decoders N and --orc-encoders N, and
// `stellwerk-cli --station URL orc find|watch` on its TCP port, as a user runs them. What the central finds
// and sees is what the simulator's options put on its bus.

#include "CliApplication.h"
#include "SimProgram.h"

#include <QCoreApplication>
#include <QProcess>
#include <gtest/gtest.h>

namespace stellwerk::cli {
namespace {

struct CliRun {
    int status = -1;
    QString out;
};

// stellwerk-cli --station tcp://127.0.0.1:PORT orc ARGUMENTS..., until it ends.
CliRun orc(std::uint16_t port, const QStringList& arguments) {
    QProcess cli;
    cli.start(STELLWERK_CLI,
              QStringList{"--station", QStringLiteral("tcp://127.0.0.1:%1").arg(port), "orc"} + arguments);
    support::runEventsUntil([&] { return cli.state() == QProcess::NotRunning; }, 20000);
    return {cli.exitCode(), QString::fromUtf8(cli.readAllStandardOutput())};
}

TEST(SimOrcCommand, OrcFindListsWhatTheSimulatorsOptionsPutOnItsBus) {
    test::ensureApplication();
    support::SimProgram sim(QStringList{"--orc-booster", "--orc-decoders", "2", "--orc-encoders", "1"} +
                            support::Quiet);
    const std::uint16_t port = sim.tcpPort();
    ASSERT_NE(port, 0) << sim.output().toStdString();
    const CliRun found = orc(port, {"find"});
    EXPECT_EQ(found.status, 0) << found.out.toStdString();
    for (const char* line : {"device uid=0x3A2E0300 busId=0x0300 type=system version=0x0102 online\n",
                             "device uid=0x3A2E0101 busId=0x0101 type=can-decoder version=0x0102 online\n",
                             "device uid=0x3A2E0102 busId=0x0102 type=can-decoder version=0x0102 online\n",
                             "device uid=0x3A2E0201 busId=0x0201 type=can-encoder version=0x0102 online\n",
                             "4 device(s) answered\n"})
        EXPECT_TRUE(found.out.contains(QString::fromLatin1(line))) << line << found.out.toStdString();
}

TEST(SimOrcCommand, OrcWatchShowsTheEncodersInputsAndTheBoostersOverload) {
    test::ensureApplication();
    support::SimProgram sim(QStringList{"--orc-booster", "--orc-overload-after", "300", "--orc-encoders", "1",
                                        "--orc-encoder-toggle", "200"} +
                            support::Quiet);
    const std::uint16_t port = sim.tcpPort();
    ASSERT_NE(port, 0) << sim.output().toStdString();
    const CliRun watched = orc(port, {"--seconds", "2", "watch"});
    EXPECT_EQ(watched.status, 0) << watched.out.toStdString();
    EXPECT_TRUE(watched.out.contains("inputs encoder=0x0201 ")) << watched.out.toStdString();
    EXPECT_TRUE(watched.out.contains("overload busId=0x0300 port=1 kind=1\n")) << watched.out.toStdString();
    EXPECT_TRUE(watched.out.contains("overload busId=0x0300 port=1 kind=0\n")) << "cleared";
}

} // namespace
} // namespace stellwerk::cli
