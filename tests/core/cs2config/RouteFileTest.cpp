// fahrstrassen.cs2 as typed routes: the document's example, TrainControl's 81 routes, writing back byte for
// byte, edits, the diagnostics, and the check against magnetartikel.cs2.

#include "cs2config/RouteFile.h"

#include "ConfigTestSupport.h"
#include "cs2config/AccessoryFile.h"
#include "cs2config/RouteAccessoryCheck.h"
#include "cs2config/RouteDelay.h"

#include <map>
#include <random>

namespace stellwerk::cs2config::test {
namespace {

// 8.2.3 / 8.2.4: the document's fahrstrassen.cs2 example (indented by two spaces).
constexpr std::string_view documentFahrstrassen = "[fahrstrassen]\n"
                                                  "version\n"
                                                  "  .major=0\n"
                                                  "  .minor=1\n"
                                                  "fahrstrasse\n"
                                                  "  .id=1\n"
                                                  "  .name=FS1ein\n"
                                                  "  .s88=1\n"
                                                  "  .s88Ein=1\n"
                                                  "  .extern=1\n"
                                                  "  .item\n"
                                                  "  ..fsverweis=-1\n"
                                                  "  ..magnetartikel=23\n"
                                                  "  ..stellung=1\n";

using ReadRoutes = ReadModel<RouteFile>;

ReadRoutes readRoutes(std::string_view text) {
    return readAs<RouteFile>(text, "fahrstrassen.cs2");
}

Route& routeWithId(RouteFile& file, std::int64_t id) {
    for (Route& route : file.routes)
        if (route.id == id)
            return route;
    throw std::out_of_range("no route " + std::to_string(id));
}

void expectSameRoutes(const std::vector<Route>& actual, const std::vector<Route>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        SCOPED_TRACE("route " + std::to_string(expected[i].id));
        const Route& a = actual[i];
        const Route& e = expected[i];
        EXPECT_EQ(a.id, e.id);
        EXPECT_EQ(a.name, e.name);
        EXPECT_EQ(a.triggerContact, e.triggerContact);
        EXPECT_EQ(a.releaseContact, e.releaseContact);
        EXPECT_EQ(a.mode, e.mode);
        ASSERT_EQ(a.conditions.size(), e.conditions.size());
        for (std::size_t c = 0; c < a.conditions.size(); ++c) {
            EXPECT_EQ(a.conditions[c].contact, e.conditions[c].contact);
            EXPECT_EQ(a.conditions[c].occupied, e.conditions[c].occupied);
        }
        ASSERT_EQ(a.steps.size(), e.steps.size());
        for (std::size_t s = 0; s < a.steps.size(); ++s) {
            EXPECT_EQ(a.steps[s].type, e.steps[s].type);
            EXPECT_EQ(a.steps[s].accessory, e.steps[s].accessory);
            EXPECT_EQ(a.steps[s].position, e.steps[s].position);
            EXPECT_EQ(a.steps[s].routeReference, e.steps[s].routeReference);
            EXPECT_EQ(a.steps[s].delayMs, e.steps[s].delayMs);
        }
    }
}

TEST(RouteFile, DocumentExampleIsRead) {
    ReadRoutes read = readRoutes(documentFahrstrassen);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    EXPECT_EQ(read.file.versionMajor, 0);
    EXPECT_EQ(read.file.versionMinor, 1);
    ASSERT_EQ(read.file.routes.size(), 1u);
    const Route& route = read.file.routes[0];
    EXPECT_EQ(route.id, 1);
    EXPECT_EQ(route.name, "FS1ein");
    EXPECT_EQ(route.triggerContact, 1);
    EXPECT_EQ(route.releaseContact, 1);
    EXPECT_EQ(route.mode, 1);
    EXPECT_TRUE(route.conditions.empty());
    ASSERT_EQ(route.steps.size(), 1u);
    const RouteStep& step = route.steps[0];
    EXPECT_EQ(step.type, "");
    EXPECT_EQ(step.routeReference, -1);
    EXPECT_FALSE(step.runsRoute());
    EXPECT_EQ(step.accessory, 23);
    EXPECT_EQ(step.position, 1);
    EXPECT_EQ(step.delayMs, std::nullopt);
    EXPECT_EQ(step.lineNumber(), 11);
    EXPECT_EQ(read.file.write().serialize(), documentFahrstrassen);
}

TEST(RouteFile, TrainControlCorpusCounts) {
    ReadRoutes read = readRoutes(readCorpus(corpus::fahrstrassen));
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    const RouteFile& file = read.file;
    EXPECT_EQ(file.versionMinor, 4);
    ASSERT_EQ(file.routes.size(), 81u);
    std::size_t steps = 0;
    std::size_t conditions = 0;
    std::size_t triggered = 0;
    std::map<std::int64_t, int> positions;
    std::map<std::int64_t, int> delays;
    std::map<std::int64_t, int> conditionContacts;
    int mustBeFree = 0;
    std::vector<std::int64_t> released;
    for (const Route& route : file.routes) {
        steps += route.steps.size();
        conditions += route.conditions.size();
        triggered += route.triggerContact != 0 ? 1 : 0;
        if (route.releaseContact) {
            released.push_back(route.id);
            EXPECT_EQ(*route.releaseContact, 0);
        }
        for (const RouteStep& step : route.steps) {
            EXPECT_EQ(step.type, "mag");
            EXPECT_FALSE(step.runsRoute());
            ++positions[step.position];
            if (step.delayMs)
                ++delays[*step.delayMs];
        }
        for (const RouteCondition& condition : route.conditions) {
            ++conditionContacts[condition.contact];
            mustBeFree += condition.occupied ? 0 : 1;
        }
    }
    EXPECT_EQ(steps, 689u);
    EXPECT_EQ(conditions, 18u);
    EXPECT_EQ(mustBeFree, 8);
    EXPECT_EQ(triggered, 29u);
    EXPECT_EQ(released, (std::vector<std::int64_t>{178, 180, 182, 184}));
    EXPECT_EQ(positions, (std::map<std::int64_t, int>{{0, 313}, {1, 367}, {3, 9}}));
    EXPECT_EQ(delays, (std::map<std::int64_t, int>{{2000, 2}, {2300, 1}, {3000, 2}, {3200, 1}, {4000, 1}}));
    EXPECT_EQ(conditionContacts,
              (std::map<std::int64_t, int>{{3, 2}, {14, 3}, {15, 4}, {34, 3}, {40, 4}, {47, 2}}));
}

TEST(RouteFile, TrainControlRoutesInDetail) {
    RouteFile file = readRoutes(readCorpus(corpus::fahrstrassen)).file;
    const Route& reset = routeWithId(file, 1);
    EXPECT_EQ(reset.name, "sk reset");
    EXPECT_EQ(reset.steps.size(), 39u);
    EXPECT_EQ(reset.steps[0].accessory, 3);
    EXPECT_EQ(reset.steps[0].position, 0);
    EXPECT_EQ(reset.steps[1].accessory, 2);
    EXPECT_EQ(reset.steps[1].position, 1);
    EXPECT_EQ(routeWithId(file, 2).steps.size(), 48u);
    EXPECT_EQ(routeWithId(file, 168).mode, 1);
    const Route& conditional = routeWithId(file, 177);
    EXPECT_EQ(conditional.name, "yi 14i");
    EXPECT_EQ(conditional.triggerContact, 14);
    ASSERT_EQ(conditional.conditions.size(), 2u);
    EXPECT_EQ(conditional.conditions[0].contact, 15);
    EXPECT_TRUE(conditional.conditions[0].occupied);
    EXPECT_EQ(conditional.conditions[1].contact, 3);
    EXPECT_FALSE(conditional.conditions[1].occupied);
    EXPECT_EQ(conditional.steps.at(0).delayMs, 2000);
    EXPECT_EQ(routeWithId(file, 146).steps.at(1).delayMs, 2300);
}

TEST(RouteFile, TrainControlRoutesSwitchAccessoriesTheKeyboardHas) {
    const RouteFile routes = readRoutes(readCorpus(corpus::fahrstrassen)).file;
    Parsed parsed = parseCorpus(corpus::magnetartikelTrainControl);
    Diagnostics ignored;
    const AccessoryFile accessories = AccessoryFile::read(parsed.document, ignored);
    Diagnostics diagnostics;
    checkRouteAccessories(routes, accessories, diagnostics);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
}

TEST(RouteFile, MissingAccessoriesAndPositionsAreReported) {
    ReadRoutes routes =
        readRoutes("[fahrstrassen]\nfahrstrasse\n .id=1\n .item\n ..typ=mag\n ..magnetartikel=5\n"
                   " ..stellung=3\n .item\n ..typ=mag\n ..magnetartikel=9\n .item\n ..fsverweis=1\n");
    Parsed parsed = parseText("[magnetartikel]\nartikel\n .id=5\n .typ=dreiwegweiche\n");
    Diagnostics ignored;
    const AccessoryFile accessories = AccessoryFile::read(parsed.document, ignored);
    Diagnostics diagnostics;
    checkRouteAccessories(routes.file, accessories, diagnostics);
    ASSERT_EQ(diagnostics.count(), 2u) << diagnostics.formatAll();
    EXPECT_EQ(diagnostics.items()[0].line, 4);
    EXPECT_EQ(diagnostics.items()[0].message,
              "route 1 switches accessory 5 to position 3, which dreiwegweiche does not have");
    EXPECT_EQ(diagnostics.items()[1].line, 8);
    EXPECT_EQ(diagnostics.items()[1].message,
              "route 1 switches accessory 9, which magnetartikel.cs2 does not have");
}

TEST(RouteFile, CorpusFileIsWrittenBackByteForByte) {
    const std::string bytes = readCorpus(corpus::fahrstrassen);
    EXPECT_EQ(readRoutes(bytes).file.write().serialize(), bytes);
}

TEST(RouteFile, ChangingOneStepChangesOnlyItsLine) {
    const std::string bytes = readCorpus(corpus::fahrstrassen);
    RouteFile file = readRoutes(bytes).file;
    RouteStep& step = routeWithId(file, 1).steps.at(1);
    step.position = 0;
    RouteStep& delayed = routeWithId(file, 146).steps.at(1);
    delayed.delayMs = 2500;
    const std::string expected =
        withLine(withLine(bytes, step.source.find("stellung")->lineNumber(), " ..stellung=0"),
                 delayed.source.find("sekunde")->lineNumber(), " ..sekunde=2.5");
    EXPECT_EQ(file.write().serialize(), expected);
}

TEST(RouteFile, EquivalentValuesKeepTheirText) {
    const std::string text = "[fahrstrassen]\nfahrstrasse\n .id=0x7\n .s88Ein=0\n .item\n ..sekunde=2.30\n"
                             " ..magnetartikel=05\n .S88Flag\n ..kont=3\n ..hi=1\n";
    ReadRoutes read = readRoutes(text);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    Route& route = read.file.routes.at(0);
    EXPECT_EQ(route.id, 7);
    EXPECT_EQ(route.steps.at(0).delayMs, 2300);
    EXPECT_EQ(route.steps.at(0).accessory, 5);
    EXPECT_TRUE(route.conditions.at(0).occupied);
    EXPECT_EQ(read.file.write().serialize(), text);
    route.releaseContact.reset();
    route.conditions.at(0).occupied = false;
    route.steps.at(0).delayMs.reset();
    EXPECT_EQ(read.file.write().serialize(),
              "[fahrstrassen]\nfahrstrasse\n .id=0x7\n .item\n ..magnetartikel=05\n"
              " .S88Flag\n ..kont=3\n ..hi=0\n");
}

TEST(RouteFile, AddedAndRemovedStepsAndConditionsReadBackTheSame) {
    RouteFile file = readRoutes(readCorpus(corpus::fahrstrassen)).file;
    Route& reset = routeWithId(file, 1);
    RouteStep added;
    added.accessory = 225;
    added.position = 1;
    added.delayMs = 1500;
    reset.steps.push_back(added);
    reset.steps.erase(reset.steps.begin());
    RouteStep runsRoute;
    runsRoute.type.clear();
    runsRoute.routeReference = 2;
    reset.steps.insert(reset.steps.begin() + 3, runsRoute);
    Route& conditional = routeWithId(file, 177);
    conditional.conditions.erase(conditional.conditions.begin());
    Route& plain = routeWithId(file, 2);
    plain.conditions.push_back({12, false, {}});
    plain.triggerContact = 9;
    plain.steps.resize(2);

    const std::string written = file.write().serialize();
    ReadRoutes again = readRoutes(written);
    EXPECT_TRUE(again.diagnostics.empty()) << again.diagnostics.formatAll();
    expectSameRoutes(again.file.routes, file.routes);
    EXPECT_NE(written.find(" .item\n ..typ=mag\n ..sekunde=1.5\n ..magnetartikel=225\n ..stellung=1\n"
                           "fahrstrasse\n .id=2\n"),
              std::string::npos);
    EXPECT_NE(written.find(" .item\n ..fsverweis=2\n .item\n"), std::string::npos);
    EXPECT_NE(
        written.find("fahrstrasse\n .id=2\n .name=si r\n .s88=9\n .S88Flag\n ..kont=12\n ..hi=0\n .item\n"),
        std::string::npos)
        << written.substr(written.find("fahrstrasse\n .id=2\n"), 120);
}

TEST(RouteFile, NewRouteIsWrittenInTheFilesStyle) {
    ReadRoutes read = readRoutes(documentFahrstrassen);
    Route route;
    route.id = 2;
    route.name = "FS2";
    route.releaseContact = 0;
    route.conditions.push_back({7, true, {}});
    RouteStep step;
    step.accessory = 24;
    route.steps.push_back(step);
    read.file.routes.push_back(route);
    EXPECT_EQ(read.file.write().serialize(),
              std::string(documentFahrstrassen) +
                  "fahrstrasse\n  .id=2\n  .name=FS2\n  .s88Ein=0\n  .S88Flag\n"
                  "  ..kont=7\n  .item\n  ..typ=mag\n  ..magnetartikel=24\n");
}

TEST(RouteFile, StepAddedToAFileWithoutFinalNewline) {
    ReadRoutes read =
        readRoutes("[fahrstrassen]\nfahrstrasse\n .id=1\n .item\n ..typ=mag\n ..magnetartikel=3");
    RouteStep step;
    step.accessory = 4;
    read.file.routes.at(0).steps.push_back(step);
    EXPECT_EQ(read.file.write().serialize(), "[fahrstrassen]\nfahrstrasse\n .id=1\n .item\n ..typ=mag\n"
                                             " ..magnetartikel=3\n .item\n ..typ=mag\n ..magnetartikel=4");
    read.file.routes.at(0).steps.clear();
    EXPECT_EQ(read.file.write().serialize(), "[fahrstrassen]\nfahrstrasse\n .id=1");
}

TEST(RouteFile, ProblemsAreReported) {
    ReadRoutes read =
        readRoutes("[fahrstrassen]\n"
                   "fahrstrasse\n .id=1\n .farbe=blau\n .item\n ..typ=s88\n ..kontakt=4\n"
                   " .item\n ..typ=s88\n .item\n ..typ=mag\n ..sekunde=zwei\n ..magnetartikel=3\n"
                   " .item\n ..typ=mag\n .S88Flag\n ..hi=0\n"
                   "fahrstrasse\n .id=1\n .item\n ..fsverweis=12\n");
    const std::vector<std::pair<int, std::string>> expected = {
        {4, "unknown key '.farbe' in fahrstrasse records"},
        {7, "unknown key '..kontakt' in route steps (.item)"},
        {5, "unknown route step type ..typ='s88'"},
        {12, "value 'zwei' of ..sekunde is not a wait in seconds"},
        {14, "route step switches neither an accessory nor a route"},
        {16, "route condition without ..kont"},
        {18, "duplicate route id 1 (first at line 2)"},
        {20, "route 1 runs route 12, which the file does not have"},
    };
    ASSERT_EQ(read.diagnostics.count(), expected.size()) << read.diagnostics.formatAll();
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(read.diagnostics.items()[i].line, expected[i].first) << i;
        EXPECT_EQ(read.diagnostics.items()[i].message, expected[i].second) << i;
    }
    EXPECT_EQ(read.file.routes.at(0).steps.at(2).delayMs, std::nullopt);
    EXPECT_EQ(read.file.write().serialize(), read.file.document.serialize());
}

TEST(RouteFile, JsonListsRoutesWithTheirSteps) {
    ReadRoutes read =
        readRoutes("[fahrstrassen]\nfahrstrasse\n .id=4\n .name=Ausfahrt\n .s88=12\n .S88Flag\n ..kont=3\n"
                   " ..hi=0\n .item\n ..typ=mag\n ..sekunde=2.3\n ..magnetartikel=7\n ..stellung=1\n");
    EXPECT_EQ(toJson(read.file), R"({
  "file": "fahrstrassen.cs2",
  "version": {
    "major": null,
    "minor": null
  },
  "routes": [
    {
      "line": 2,
      "id": 4,
      "name": "Ausfahrt",
      "triggerContact": 12,
      "releaseContact": null,
      "mode": 0,
      "conditions": [
        {
          "line": 6,
          "contact": 3,
          "occupied": false
        }
      ],
      "steps": [
        {
          "line": 9,
          "type": "mag",
          "route": null,
          "accessory": 7,
          "position": 1,
          "delayMs": 2300
        }
      ]
    }
  ]
}
)");
}

TEST(RouteDelay, SecondsWithDecimalsAreMilliseconds) {
    EXPECT_EQ(parseRouteDelay("2"), 2000);
    EXPECT_EQ(parseRouteDelay("2.3"), 2300);
    EXPECT_EQ(parseRouteDelay("3.25"), 3250);
    EXPECT_EQ(parseRouteDelay("0.005"), 5);
    EXPECT_EQ(parseRouteDelay(" 4 "), 4000);
    EXPECT_EQ(parseRouteDelay("99999999.999"), 99999999999);
    for (std::string_view bad : {"", "abc", "-1", "2.", ".5", "1.2345", "123456789", "2,3", "1e3", "0x10"})
        EXPECT_EQ(parseRouteDelay(bad), std::nullopt) << bad;
    EXPECT_EQ(formatRouteDelay(2300), "2.3");
    EXPECT_EQ(formatRouteDelay(4000), "4");
    EXPECT_EQ(formatRouteDelay(250), "0.25");
    EXPECT_EQ(formatRouteDelay(5), "0.005");
    EXPECT_EQ(formatRouteDelay(-3), "0");
}

TEST(RouteFile, DamagedFilesAreReadAndWrittenBack) {
    const std::string original = readCorpus(corpus::fahrstrassen);
    std::mt19937 random(4711);
    for (int round = 0; round < 2000; ++round) {
        const std::string bytes = damaged(original, random);
        Parsed parsed = parseText(bytes);
        ASSERT_EQ(parsed.document.serialize(), bytes) << "round " << round;
        const RouteFile file = RouteFile::read(parsed.document, parsed.diagnostics);
        const std::string written = file.write().serialize();
        if (recordsGrouped(parsed.document, RouteFile::recordKeyword)) {
            ASSERT_EQ(written, bytes) << "round " << round;
        }
        Diagnostics again;
        RouteFile::read(Document::parse(written, again), again);
    }
}

} // namespace
} // namespace stellwerk::cs2config::test
