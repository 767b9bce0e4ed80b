#pragma once

// The main window on a simulated CS2 (TCP, loopback) with a further bus: a CAN-to-TCP gateway with RO
// module "RO 1", an OpenRailCAN decoder and an encoder behind it, and the railway's devices bound the way
// the GUI program binds them. Settings are the program's own, cleared before and after.

#include "DeviceBusPeer.h"
#include "EventLoopWait.h"
#include "binding/RailwayBinding.h"
#include "common/StellwerkSettings.h"
#include "connection/StationConnection.h"
#include "devices/DeviceTableModel.h"
#include "devices/DevicesPanel.h"
#include "model/Railway.h"
#include "model/RailwayDevices.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "shell/Workspace.h"
#include "sim/SimulatedOrcDevices.h"
#include "sim/SimulatedRoModule.h"
#include "support/StationTestSupport.h"

#include <QTableView>
#include <QTest>
#include <gtest/gtest.h>
#include <memory>

namespace stellwerk::ui::test {

inline constexpr int DeviceWaitMs = 10000;
inline constexpr std::uint32_t DecoderUid = 0x3A2E0007;
inline constexpr std::uint32_t EncoderUid = 0x3A2E0008;

// Another program on the device bus: it sends what a test gives it and ignores what it hears.
class OtherProgram final : public QObject {
    Q_OBJECT

public:
    void receive(const can::CanFrame&) {}
    void send(const std::vector<can::CanFrame>& frames) { emit framesEmitted(frames); }

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);
};

inline connection::ConnectionSettings deviceConnectionSettings() {
    connection::RoModuleSettings module;
    module.profile = ro::RoProfile::simulator(1);
    module.profile.name = "RO 1";
    module.bus = 1;
    module.pollPeriod = std::chrono::milliseconds(100);
    connection::ConnectionSettings settings;
    settings.devices.orc.on = true;
    settings.devices.orc.bus = 1;
    settings.devices.roModules.push_back(module);
    return settings;
}

class DevicesRig : public ::testing::Test {
protected:
    void SetUp() override {
        stellwerkSettings().clear();
        ASSERT_TRUE(translations.select(Language::English));
        decoder.plugIn();
        encoder.plugIn();
        gateway.bus.attach(module);
        gateway.bus.attach(decoder);
        gateway.bus.attach(encoder);
        gateway.bus.attach(otherProgram);
        ASSERT_TRUE(gateway.listen());
        ASSERT_TRUE(station.start());
        window = std::make_unique<MainWindow>(translations);
        railways = std::make_unique<binding::RailwayBinding>(connection);
        QObject::connect(railways.get(), &binding::RailwayBinding::railwayChanged, window.get(),
                         [this](model::Railway* railway) { bind(railway); });
        window->setConnection(&connection);
        window->resize(1366, 768);
        window->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
        panel = window->findChild<DevicesPanel*>();
        ASSERT_NE(panel, nullptr);
        window->workspace()->showPanel(panel);
        connection.connectTo(station.url(), {gateway.url()});
        ASSERT_TRUE(waitForState(connection, connection::StationConnection::State::Ready));
        ASSERT_TRUE(waitUntil([&] { return everythingOnline(); })) << panel->summaryText().toStdString();
    }
    void TearDown() override {
        railways.reset();
        window.reset();
        stellwerkSettings().clear();
    }

    // The GUI program's wiring (app/gui): the railway's devices with the saved bindings, following the
    // connection's device sessions.
    void bind(model::Railway* railway) {
        if (railway) {
            QSettings saved = stellwerkSettings();
            auto* devices = new model::RailwayDevices(*railway, model::DeviceBindings::load(saved), railway);
            const auto follow = [this, devices] {
                devices->setSessions(connection.devices().orcSession(), connection.devices().roModules());
            };
            QObject::connect(&connection.devices(), &connection::ConnectionDevices::devicesChanged, devices,
                             follow);
            follow();
        }
        window->setRailway(railway);
    }
    static bool waitUntil(const std::function<bool()>& done, int timeoutMs = DeviceWaitMs) {
        return support::runEventsUntil(done, timeoutMs);
    }
    bool everythingOnline() const {
        return panel->summaryText() ==
               QStringLiteral("OpenRailCAN: 2 of 2 devices online. RO modules: 1 of 1 online.");
    }
    QString cell(int row, int column) const {
        return panel->table().data(panel->table().index(row, column)).toString();
    }
    int rowOfModule() const { return panel->table().rowOf({false, 0, QStringLiteral("RO 1")}); }
    model::RailwayDevices* railwayDevices() const {
        return railways->railway() ? railways->railway()->findChild<model::RailwayDevices*>() : nullptr;
    }

    Translations translations;
    TestStation station;
    support::DeviceBusPeer gateway;
    sim::SimulatedRoModule module{ro::RoProfile::simulator(1)};
    sim::SimulatedOrcDecoder decoder{DecoderUid};
    sim::SimulatedOrcEncoder encoder{EncoderUid};
    OtherProgram otherProgram;
    connection::StationConnection connection{deviceConnectionSettings()};
    std::unique_ptr<MainWindow> window;
    std::unique_ptr<binding::RailwayBinding> railways;
    DevicesPanel* panel = nullptr;
};

} // namespace stellwerk::ui::test
