// The real stellwerk-cli binary: arguments, stdin, exit status.

#include <array>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>

namespace {

struct Process {
    int status;
    std::string out;
};

Process run(const std::string& arguments) {
    const std::string command = std::string(STELLWERK_CLI) + " " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    EXPECT_NE(pipe, nullptr);
    std::string out;
    std::array<char, 512> buffer{};
    while (pipe && std::fgets(buffer.data(), int(buffer.size()), pipe))
        out += buffer.data();
    const int status = pipe ? pclose(pipe) : -1;
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

} // namespace

TEST(CliProcess, DecodesTheCorpusStreamLogFromStdin) {
    const std::string log =
        std::string(STELLWERK_SHARED_DIR) + "/corpus/GBert__railroad/can2udp/src/example_zlib.txt";
    const auto result = run("decode < '" + log + "'");
    EXPECT_EQ(result.status, 0) << result.out;
    EXPECT_NE(
        result.out.find("00420300 7 00 00 00 5F 21 70 7B  configdata.stream form=broadcast-header length=95 "
                        "crc=0x2170 value=0x7B\n"),
        std::string::npos)
        << result.out;
    std::size_t lines = 0;
    for (char c : result.out)
        lines += c == '\n';
    EXPECT_EQ(lines, 13u);
}

TEST(CliProcess, ExitStatusIsOneWhenAFrameIsBad) {
    const auto result = run("decode '00084711 6 00 00 C0 03 01 20' '00084711 2 00 00'");
    EXPECT_EQ(result.status, 1);
    EXPECT_NE(result.out.find("loco.speed locId=0xC003"), std::string::npos);
    EXPECT_NE(result.out.find("too short"), std::string::npos);
}

TEST(CliProcess, EncodeOutputDecodesBackToTheSameMessage) {
    const auto encoded =
        run("encode accessory.switch protocol=dcc-accessory address=12 position=1 current=1");
    ASSERT_EQ(encoded.status, 0) << encoded.out;
    const auto candump = encoded.out.substr(encoded.out.find("candump:  ") + 10, 21);
    const auto decoded = run("decode " + candump);
    EXPECT_EQ(decoded.status, 0);
    EXPECT_NE(decoded.out.find(
                  "accessory.switch locId=0x380B protocol=dcc-accessory address=12 position=1 current=1"),
              std::string::npos)
        << decoded.out;
}

TEST(CliProcess, UsageAndVersion) {
    EXPECT_EQ(run("").status, 2);
    EXPECT_EQ(run("frobnicate").status, 2);
    const auto help = run("--help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("stellwerk-cli decode [--json] [FRAME ...]"), std::string::npos);
    EXPECT_NE(run("--version").out.find("stellwerk-cli 0."), std::string::npos);
}
