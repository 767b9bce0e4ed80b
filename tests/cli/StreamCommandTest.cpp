// `stellwerk-cli stream decode|encode`: config-data streams from captures into files, and files
// into the frames a CS2 sends.

#include "StreamCommand.h"

#include "CliTestSupport.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <sys/wait.h>

using stellwerk::cli::runStream;
using stellwerk::cli::test::corpus;
using stellwerk::cli::test::Outcome;
using stellwerk::cli::test::readFile;
namespace fs = std::filesystem;

namespace {

Outcome stream(std::vector<std::string> arguments, const std::string& input = {}) {
    std::istringstream in(input);
    std::ostringstream out, err;
    const int status = runStream(arguments, in, out, err);
    return {status, out.str(), err.str()};
}

const std::string CorpusLog = "GBert__railroad/can2udp/src/example_zlib.txt";
const std::string CorpusLocos = "bob123456678__TrainControl/test/lokomotive.cs2";

// A fresh output directory per test, removed afterwards.
class CliStream : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("stellwerk-stream-" + std::to_string(std::random_device{}()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    Outcome decode(const std::string& input, std::vector<std::string> extra = {}) {
        std::vector<std::string> arguments{"decode", "-d", dir_.string()};
        arguments.insert(arguments.end(), extra.begin(), extra.end());
        return stream(arguments, input);
    }
    std::string encoded(std::vector<std::string> arguments) {
        arguments.insert(arguments.begin(), "encode");
        const auto run = stream(arguments);
        EXPECT_EQ(run.status, 0) << run.err;
        return run.out;
    }

    fs::path dir_;
};

} // namespace

TEST_F(CliStream, DecodesTheCorpusLogIntoTheGleisbildPage) {
    const auto run = decode("", {corpus(CorpusLog)});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, "stream-1.cs2: 170 bytes, CRC 0x2170 ok, compressed, broadcast from hash 0x0300\n");
    EXPECT_EQ(run.err, "");
    const std::string page = readFile(dir_ / "stream-1.cs2");
    EXPECT_EQ(page.size(), 170u);
    EXPECT_EQ(page.rfind("[gleisbildseite]\n", 0), 0u);
}

TEST_F(CliStream, NamesTheFileAfterTheRequestedKey) {
    const auto frames = encoded({corpus(CorpusLocos), "--key", "loks", "--hash", "0x4711"});
    const auto run = decode(frames);
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out.rfind("lokomotive.cs2: 68964 bytes, CRC 0x", 0), 0u) << run.out;
    EXPECT_NE(run.out.find(" ok, compressed, to hash 0x4711\n"), std::string::npos) << run.out;
    EXPECT_EQ(readFile(dir_ / "lokomotive.cs2"), readFile(corpus(CorpusLocos)));
}

TEST_F(CliStream, TrackPlanPageKeepsItsNumber) {
    const auto run = decode(encoded({corpus("GBert__railroad/can2udp/src/gbs-0.cs2"), "--key", "gbs-0"}));
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(readFile(dir_ / "gbs-0.cs2"), readFile(corpus("GBert__railroad/can2udp/src/gbs-0.cs2")));
}

TEST_F(CliStream, CandumpNotationRoundTrips) {
    const auto frames = encoded({corpus(CorpusLocos), "--key", "loks", "--notation", "candump"});
    EXPECT_EQ(frames.rfind("00414711#6C6F6B7300000000\n00424711#", 0), 0u) << frames.substr(0, 80);
    EXPECT_EQ(decode(frames).status, 0);
    EXPECT_EQ(readFile(dir_ / "lokomotive.cs2"), readFile(corpus(CorpusLocos)));
}

TEST_F(CliStream, ReadsStandardInputAndStoresRepeatedKeysUnderNewNames) {
    const auto frames = encoded({corpus(CorpusLocos), "--key", "loks"});
    const auto run = decode(frames + frames);
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_TRUE(fs::exists(dir_ / "lokomotive.cs2"));
    EXPECT_TRUE(fs::exists(dir_ / "lokomotive-2.cs2"));
}

TEST_F(CliStream, BrokenStreamIsReportedAndTheExitStatusIsOne) {
    std::string log = readFile(corpus(CorpusLog));
    log.replace(log.find("cf 49 cd 2c"), 11, "cf 49 cd 2d"); // one bit in the second data frame
    const auto good = encoded({corpus(CorpusLocos), "--key", "loks"});
    const auto run = decode(log + good);
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(
        run.err.rfind(
            "stellwerk-cli stream decode: line 13: stream 1: broadcast stream (hash 0x0300): CRC mismatch: "
            "the header announces 0x2170, the 96 received bytes give 0x",
            0),
        0u)
        << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "stream-1.cs2"));
    EXPECT_TRUE(fs::exists(dir_ / "lokomotive.cs2")); // the next stream is still stored
}

TEST_F(CliStream, StreamCutShortIsReportedAtTheEnd) {
    const auto frames = encoded({corpus(CorpusLocos), "--key", "loks"});
    const auto run = decode(frames.substr(0, frames.size() / 2));
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(
        run.err.find("stellwerk-cli stream decode: end of input: stream 1: stream for 'loks' (hash 0x4711): "
                     "the input ended after "),
        std::string::npos)
        << run.err;
}

TEST_F(CliStream, UnreadableLinesAreSkippedWithAWarning) {
    const auto run = decode("# capture\n\nhello world\n" + readFile(corpus(CorpusLog)));
    EXPECT_EQ(run.status, 0);
    EXPECT_NE(run.err.find("stellwerk-cli stream decode: line 3: "), std::string::npos) << run.err;
    EXPECT_TRUE(fs::exists(dir_ / "stream-1.cs2"));
}

TEST_F(CliStream, MissingInputFile) {
    const auto run = decode("", {(dir_ / "nothing.txt").string()});
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.err.find("cannot read"), std::string::npos);
}

TEST_F(CliStream, EncodeBroadcastHasTheSevenByteHeaderAndNoAcknowledgement) {
    const auto frames = encoded({corpus(CorpusLocos), "--key", "loks", "--hash", "0x0300", "--broadcast"});
    EXPECT_EQ(frames.rfind("00420300 7 00 00 ", 0), 0u) << frames.substr(0, 60);
    EXPECT_EQ(frames.substr(frames.find('\n') - 3, 3), " 7B");
    const auto run = decode(frames);
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("stream-1.cs2: 68964 bytes"), std::string::npos) << run.out;
}

TEST_F(CliStream, EncodeMs2TextIsPlainWithItsFollowUpInTheAcknowledgement) {
    const fs::path text = dir_ / "lokinfo.txt";
    std::ofstream(text) << "[lokomotive]\nlok\n .name=M4\n";
    const auto frames = encoded({text.string(), "--key", "lokinfo", "--follow-up", "M4"});
    EXPECT_EQ(frames.rfind("00414711 8 6C 6F 6B 69 6E 66 6F 00\n"
                           "00414711 8 4D 34 00 00 00 00 00 00\n"
                           "00414711 8 00 00 00 00 00 00 00 00\n"
                           "00424711 6 00 00 00 28 ", // 40 bytes: each line padded to a frame
                           0),
              0u)
        << frames;
    EXPECT_NE(frames.find("00424711 8 5B 6C 6F 6B 6F 6D 6F 74\n"), std::string::npos); // "[lokomot", plain
}

// Issue 11 (found by fuzzing): bytes 4-5 of this text ("x ") look like a zlib header after a size
// prefix; the receiver took the plain file for a compressed one and refused it.
TEST_F(CliStream, SmallPlainFileThatLooksCompressedRoundTrips) {
    const fs::path text = dir_ / "ldbver.txt";
    std::ofstream(text) << "abcdx 1\n";
    const auto run = decode(encoded({text.string(), "--key", "ldbver"}));
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("ldbver.cs2: 8 bytes, CRC "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(" ok, plain, to hash 0x4711"), std::string::npos) << run.out;
    EXPECT_EQ(readFile(dir_ / "ldbver.cs2"), "abcdx 1\n");
}

// Without a key (a broadcast) the receiver tries to inflate and takes the plain text when that fails.
TEST_F(CliStream, SmallPlainBroadcastThatLooksCompressedRoundTrips) {
    const fs::path text = dir_ / "lokinfo.txt";
    std::ofstream(text) << "abcdx 1\n";
    const auto run = decode(encoded({text.string(), "--key", "lokinfo", "--broadcast"}));
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find(" ok, plain, broadcast from hash 0x4711"), std::string::npos) << run.out;
    EXPECT_EQ(readFile(dir_ / "stream-1.cs2"), "abcdx 1\n");
}

TEST(CliStreamUsage, ErrorsAreUsageErrors) {
    EXPECT_EQ(stream({}).status, 2);
    EXPECT_EQ(stream({"frobnicate"}).status, 2);
    EXPECT_EQ(stream({"decode", "--json"}).status, 2);
    EXPECT_EQ(stream({"decode", "a.txt", "b.txt"}).status, 2);
    EXPECT_EQ(stream({"encode"}).status, 2);
    EXPECT_EQ(stream({"encode", "file.cs2"}).status, 2);
    EXPECT_EQ(stream({"encode", "file.cs2", "--key"}).status, 2);
    EXPECT_EQ(stream({"encode", "file.cs2", "--key", "loks", "--hash", "0x12345"}).status, 2);
    EXPECT_EQ(stream({"encode", "file.cs2", "--key", "loks", "--notation", "json"}).status, 2);
    EXPECT_EQ(stream({"encode", "file.cs2", "--key", "lokomotive"}).status, 2);
    EXPECT_EQ(stream({"encode", "file.cs2", "--key", "loks", "--follow-up", "1 2"}).status, 2);
    const auto run = stream({"encode", "file.cs2", "--key", "lokomotive"});
    EXPECT_EQ(run.err, "stellwerk-cli stream encode: config key 'lokomotive' must have 1 to 8 bytes\n");
}

TEST(CliStreamUsage, UnreadableFileToEncode) {
    const auto run = stream({"encode", "/nonexistent/file.cs2", "--key", "loks"});
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.err, "stellwerk-cli stream encode: cannot read /nonexistent/file.cs2\n");
}

// The real binary: dispatch from main and the exit status.
TEST_F(CliStream, ProcessDecodesTheCorpusLogFromStdin) {
    const std::string command = std::string(STELLWERK_CLI) + " stream decode -d '" + dir_.string() + "' < '" +
                                corpus(CorpusLog) + "' 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string out;
    std::array<char, 256> buffer{};
    while (std::fgets(buffer.data(), int(buffer.size()), pipe))
        out += buffer.data();
    const int status = pclose(pipe);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
    EXPECT_EQ(out, "stream-1.cs2: 170 bytes, CRC 0x2170 ok, compressed, broadcast from hash 0x0300\n");
    EXPECT_EQ(fs::file_size(dir_ / "stream-1.cs2"), 170u);
}
