// `stellwerk-cli layout graph DIR [--json]`: the blocks, connections and problems of a layout folder's
// track plan, as text and as one JSON document; exit 1 without a usable plan, 2 on a usage error.

#include "CliTestSupport.h"
#include "LayoutCommand.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <array>
#include <cstdio>
#include <gtest/gtest.h>
#include <sstream>
#include <sys/wait.h>

using stellwerk::cli::runLayout;
using stellwerk::cli::test::corpus;
using stellwerk::cli::test::Outcome;

namespace {

const std::string demoFolder = STELLWERK_DEMO_LAYOUT_FOLDER;

Outcome layout(const std::vector<std::string>& arguments) {
    std::ostringstream out, err;
    const int status = runLayout(arguments, out, err);
    return {status, out.str(), err.str()};
}

QJsonObject jsonOf(const Outcome& outcome) {
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(QByteArray::fromStdString(outcome.out), &error);
    EXPECT_EQ(error.error, QJsonParseError::NoError) << outcome.out;
    return document.object();
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST(LayoutGraphCommand, TheDemoAsText) {
    const Outcome outcome = layout({"graph", demoFolder});
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    EXPECT_EQ(outcome.err, "");
    for (const char* line : {
             "9 blocks, 20 connections, 3 problems on 3 pages\n",
             "  3 'Einfahrt West': contacts 7; 6 tiles, 900 mm\n",
             "      a: page 'Bahnhof' column 3 row 5 (east), then junction\n",
             "      signal 'A' at 270 mm, for trains towards a\n",
             "block 3 'Einfahrt West' a -> block 4 'Gleis 1' a: turnout 1 straight; 1 tile, 180 mm; routes "
             "1; "
             "conflicts with 1, 4, 7\n",
             "block 7 'Block 2' b -> block 8 'Block 3' a: no turnout; 0 tiles, 0 mm\n",
             "  page 'Bw', column 3, row 1: These 8 tiles of track between turnout 4 and a buffer stop have "
             "no "
             "contact",
         })
        EXPECT_TRUE(contains(outcome.out, line)) << line << "\n" << outcome.out;
}

TEST(LayoutGraphCommand, TheDemoAsJson) {
    // The config folder itself works as well as the folder holding it.
    const Outcome outcome = layout({"graph", demoFolder + "/config", "--json"});
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    const QJsonObject json = jsonOf(outcome);
    EXPECT_EQ(json["blocks"].toArray().size(), 9);
    EXPECT_EQ(json["connections"].toArray().size(), 20);
    EXPECT_EQ(json["problems"].toArray().size(), 3);
    EXPECT_EQ(json["pages"].toArray()[1].toObject()["name"].toString(), "Strecke");
    const QJsonObject gleis1 = json["blocks"].toArray()[3].toObject();
    EXPECT_EQ(gleis1["name"].toString(), "Gleis 1");
    EXPECT_EQ(gleis1["contacts"].toArray(), QJsonArray{1});
    const QJsonObject connection = json["connections"].toArray()[0].toObject();
    EXPECT_EQ(connection["from"].toObject(), (QJsonObject{{"block", 1}, {"end", "a"}}));
    EXPECT_EQ(connection["to"].toObject(), (QJsonObject{{"block", 3}, {"end", "a"}}));
    const QJsonObject turnout = connection["turnouts"].toArray()[0].toObject();
    EXPECT_EQ(turnout["article"].toInt(), 1);
    EXPECT_EQ(turnout["position"].toString(), "diverging");
    EXPECT_EQ(turnout["facing"].toBool(), false); // from Gleis 2 into W1's diverging leg
}

TEST(LayoutGraphCommand, ACorpusFolderAsJsonKeepsTheContactNumbersAsThePageWritesThem) {
    const Outcome outcome = layout({"graph", corpus("GBert__railroad/can2udp/files/maerklin"), "--json"});
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    const QJsonObject json = jsonOf(outcome);
    const QJsonArray blocks = json["blocks"].toArray();
    ASSERT_EQ(blocks.size(), 3);
    EXPECT_EQ(blocks[0].toObject()["name"].toString(), "603");
    EXPECT_EQ(blocks[0].toObject()["contacts"].toArray(), QJsonArray{101});
    EXPECT_EQ(blocks[0].toObject()["contactPlaces"].toArray()[0].toObject()["device"].toInt(), 0x100);
    EXPECT_EQ(json["connections"].toArray().size(), 0);
    EXPECT_EQ(json["problems"].toArray().size(), 10);
    const QJsonObject problem = json["problems"].toArray()[2].toObject();
    EXPECT_EQ(problem["x"].toInt(), 1);
    EXPECT_EQ(problem["y"].toInt(), 2);
    EXPECT_EQ(problem["kind"].toString(), "open-end");
}

TEST(LayoutGraphCommand, AFolderWithoutAPlanIsExitOne) {
    QTemporaryDir empty;
    const Outcome outcome = layout({"graph", empty.path().toStdString()});
    EXPECT_EQ(outcome.status, 1);
    EXPECT_EQ(outcome.out, "");
    EXPECT_TRUE(contains(outcome.err, "there is no track plan (config/gleisbild.cs2, or pages in config/gleisbilder/)")) << outcome.err;
}

TEST(LayoutGraphCommand, AnIndexWhosePagesAreAllMissingIsExitOne) {
    // MrFlexi's gleisbild.cs2 lists eleven pages and comes without their files.
    const Outcome outcome = layout({"graph", corpus("MrFlexi__TrainControll")});
    EXPECT_EQ(outcome.status, 1);
    EXPECT_TRUE(contains(outcome.err, "no page of the track plan in")) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "could be read")) << outcome.err;
}

TEST(LayoutGraphCommand, UsageErrorsAreExitTwo) {
    for (const std::vector<std::string>& arguments : std::vector<std::vector<std::string>>{
             {}, {"plan"}, {"graph"}, {"graph", demoFolder, "--yaml"}, {"graph", demoFolder, demoFolder}}) {
        const Outcome outcome = layout(arguments);
        EXPECT_EQ(outcome.status, 2);
        EXPECT_TRUE(contains(outcome.err, "usage: stellwerk-cli layout graph DIR [--json]")) << outcome.err;
    }
}

TEST(LayoutGraphCommand, TheProgramRunsIt) {
    const std::string command = std::string(STELLWERK_CLI) + " layout graph '" + demoFolder + "' --json";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string out;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), int(buffer.size()), pipe))
        out += buffer.data();
    const int status = pclose(pipe);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_EQ(jsonOf({0, out, {}})["blocks"].toArray().size(), 9);
}
