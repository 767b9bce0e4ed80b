#pragma once

// Helpers for the tests of trust during a running session: what reached the wire, and the main window on
// a simulated CS2 on loopback that can fall silent and come back on the same port.

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "common/StellwerkSettings.h"
#include "cs2/Codec.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "sim/EmbeddedStation.h"
#include "support/StationTestSupport.h"

#include <QTest>
#include <gtest/gtest.h>
#include <memory>
#include <variant>

namespace stellwerk::ui::test {

// Counts the system commands a connection wrote to the wire (its outgoing framesSeen).
class WireWatch {
public:
    explicit WireWatch(const connection::StationConnection& station) {
        QObject::connect(&station.buses(), &connection::ConnectionBuses::stationFramesSeen, &context_,
                         [this](const std::vector<can::CanFrame>& frames, bool outgoing) {
                             if (outgoing)
                                 for (const can::CanFrame& frame : frames)
                                     count(frame);
                         });
    }
    int stops() const { return stops_; }
    int goes() const { return goes_; }

private:
    void count(const can::CanFrame& frame) {
        const cs2::DecodeResult decoded = cs2::decode(frame);
        if (!decoded.hasValue() || decoded.value().response)
            return;
        stops_ += std::holds_alternative<cs2::SystemStop>(decoded.value().body) ? 1 : 0;
        goes_ += std::holds_alternative<cs2::SystemGo>(decoded.value().body) ? 1 : 0;
    }

    QObject context_;
    int stops_ = 0;
    int goes_ = 0;
};

// The main window on a TestStation, ready, with track power on (switched on by us: a CS2 starts in STOP).
class DeskOnTestStation : public ::testing::Test {
protected:
    static constexpr int CommandMs = 5000;

    // The window's size at its first show and the language it starts in; a test can ask for others.
    virtual QSize deskSize() const { return {1366, 768}; }
    virtual Language deskLanguage() const { return Language::English; }

    void SetUp() override {
        stellwerkSettings().clear();
        ASSERT_TRUE(translations.select(deskLanguage()));
        ASSERT_TRUE(server.start());
        window = std::make_unique<MainWindow>(translations);
        railways = std::make_unique<binding::RailwayBinding>(connection, &layout);
        window->setLayoutInUse(&layout);
        QObject::connect(railways.get(), &binding::RailwayBinding::railwayChanged, window.get(),
                         &MainWindow::setRailway);
        window->setConnection(&connection);
        window->resize(deskSize());
        window->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
        connection.connectTo(server.url());
        ASSERT_TRUE(waitForState(connection, connection::StationConnection::State::Ready));
        ASSERT_TRUE(QTest::qWaitFor([this] { return railway() && railway()->isStateReported(); }, CommandMs));
        railway()->go();
        ASSERT_TRUE(powerBecomes(station::PowerState::Running));
    }
    // The railway goes before the window, as when a session ends while the window stays.
    void TearDown() override {
        railways.reset();
        window.reset();
        stellwerkSettings().clear();
    }

    model::Railway* railway() const { return railways->railway(); }
    std::optional<station::PowerState> power() const { return railway() ? railway()->power() : std::nullopt; }
    bool powerBecomes(station::PowerState state) const {
        return QTest::qWaitFor([this, state] { return power() == state; }, CommandMs);
    }
    bool reported(bool wanted) const {
        return QTest::qWaitFor([this, wanted] { return railway() && railway()->isStateReported() == wanted; },
                               3 * CommandMs);
    }

    // Like the embedded station: a new mfx decoder waits on the track to be found.
    static sim::SimulatedStation::Options deskStation() {
        sim::SimulatedStation::Options options;
        options.newMfxDecoders = {sim::EmbeddedStation::NewMfxDecoder};
        return options;
    }

    Translations translations;
    TestStation server{deskStation()};
    connection::StationConnection connection{
        support::withEmbeddedStation()}; // outlives the railway and the window
    model::LayoutInUse layout;           // outlives the window
    std::unique_ptr<MainWindow> window;
    std::unique_ptr<binding::RailwayBinding> railways;
};

} // namespace stellwerk::ui::test
