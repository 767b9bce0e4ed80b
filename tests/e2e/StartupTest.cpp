// Document 7.1/7.2 end to end: the start-up over TCP downloads every configuration file the simulated
// station serves, and each one arrives exactly as the layout holds it.

#include "E2eSupport.h"
#include "cs2config/TrackLayout.h"
#include "station/StartupSequence.h"

#include <set>

namespace stellwerk::e2e {
namespace {

// The keys the station serves for its layout: the four files and one per track plan page.
std::set<std::string> servedKeys(const sim::StationLayout& layout) {
    std::set<std::string> keys{"loks", "mags", "fs", "gbs"};
    for (const auto& page : layout.trackPlan().pages)
        keys.insert(cs2config::trackPageStreamKey(page.id));
    return keys;
}

class StartupOverTcp : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(rig_.start()); }

    std::optional<station::StartupResult> runStartup() {
        station::StartupSequence startup(*rig_.session, {.deviceWindow = 200ms});
        std::optional<station::StartupResult> result;
        QObject::connect(&startup, &station::StartupSequence::ready,
                         [&](const station::StartupResult& r) { result = r; });
        startup.start();
        waitFor([&] { return result.has_value(); }, 3 * WaitMs);
        return result;
    }

    Rig rig_{Wire::Tcp};
};

TEST_F(StartupOverTcp, EveryFileDownloadedEqualsTheFileTheStationServes) {
    const auto result = runStartup();
    ASSERT_TRUE(result) << "the start-up did not finish";
    EXPECT_TRUE(result->problems.isEmpty()) << result->problems.join(QLatin1Char('\n')).toStdString();
    const sim::StationLayout& layout = rig_.station.layout();
    const std::set<std::string> expected = servedKeys(layout);
    ASSERT_GT(expected.size(), 4U) << "the demo layout has track plan pages";
    std::set<std::string> downloaded;
    for (const auto& [key, contents] : result->files) {
        downloaded.insert(key);
        const auto served = layout.fileForKey(key);
        ASSERT_TRUE(served) << key;
        EXPECT_TRUE(contents == *served)
            << key << ": " << contents.size() << " bytes downloaded, " << served->size() << " served";
    }
    EXPECT_EQ(downloaded, expected);
}

TEST_F(StartupOverTcp, ModelsAndStatesComeFromTheDownloadedFiles) {
    const auto result = runStartup();
    ASSERT_TRUE(result);
    ASSERT_TRUE(result->locomotives);
    EXPECT_EQ(result->locomotives->locomotives.size(),
              rig_.station.layout().locomotives().locomotives.size());
    ASSERT_TRUE(result->accessories);
    ASSERT_TRUE(result->trackPlan);
    EXPECT_EQ(result->pages.size(), rig_.station.layout().trackPlan().pages.size());
    ASSERT_FALSE(result->devices.empty());
    EXPECT_EQ(result->devices.front().identity.uid, rig_.station.uid());
    EXPECT_GT(result->stateQueries, 0U);
    EXPECT_EQ(result->stateAnswers, result->stateQueries);
}

} // namespace
} // namespace stellwerk::e2e
