#pragma once

// The fixture the track plan's block tests share: the plan panel on a railway bound to the demo layout's
// simulated CS2 served on loopback (without moving trains), with the layout in use and the blocks hidden,
// 1000x620, in English.

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "connection/StationConnection.h"
#include "model/LayoutInUse.h"
#include "shell/Translations.h"
#include "support/StationTestSupport.h"
#include "trackplan/BlockViewSettings.h"
#include "trackplan/TrackPlanPanel.h"

#include <gtest/gtest.h>
#include <memory>

namespace stellwerk::ui::test {

class TrackPlanOnDemoStation : public ::testing::Test {
protected:
    void SetUp() override {
        BlockViewSettings::setShown(false);
        ASSERT_TRUE(translations.select(Language::English));
        ASSERT_TRUE(server.start());
        panel = std::make_unique<TrackPlanPanel>();
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, panel.get(),
                         &TrackPlanPanel::setRailway);
        panel->setLayoutInUse(&layout);
        station.connectTo(server.url());
        ASSERT_TRUE(waitForState(station, connection::StationConnection::State::Ready));
        ASSERT_NE(railways.railway(), nullptr);
        panel->resize(1000, 620);
        panel->show();
    }
    void TearDown() override {
        BlockViewSettings::setShown(false);
        ASSERT_TRUE(translations.select(Language::English));
    }

    Translations translations;
    TestStation server;
    connection::StationConnection station{support::withEmbeddedStation()};
    model::LayoutInUse layout;
    binding::RailwayBinding railways{station, &layout};
    std::unique_ptr<TrackPlanPanel> panel;
};

} // namespace stellwerk::ui::test
