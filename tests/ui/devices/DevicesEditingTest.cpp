// Editing on the Devices panel (issue 15): an RO module is added with its ids and register layout only when
// it can work, and saved with the station settings; Escape leaves everything as it was; a module is
// removed; bindings made in the panel switch the module's relay from the railway and are saved.

#include "devices/BindingsDialog.h"
#include "devices/DevicesRig.h"
#include "devices/RoModuleDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>

namespace stellwerk::ui::test {
namespace {

QLineEdit* field(QWidget& dialog, const char* name) {
    return dialog.findChild<QLineEdit*>(QString::fromLatin1(name));
}

bool okEnabled(QWidget& dialog) {
    return dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled();
}

connection::DeviceSettings saved() {
    QSettings settings = stellwerkSettings();
    return connection::DeviceSettings::load(settings);
}

using DevicesEditingTest = DevicesRig;

TEST_F(DevicesEditingTest, AModuleIsAddedOnlyWhenItCanWorkAndIsSaved) {
    RoModuleDialog* dialog = panel->editModule(QString());
    ASSERT_NE(dialog, nullptr);
    EXPECT_FALSE(okEnabled(*dialog)) << "no name yet";
    EXPECT_EQ(dialog->problem(), QStringLiteral("The module needs a name."));
    field(*dialog, "moduleName")->setText(QStringLiteral("RO 1"));
    EXPECT_EQ(dialog->problem(), QStringLiteral("Another module is called \"RO 1\"."));
    field(*dialog, "moduleName")->setText(QStringLiteral("Relais Süd"));
    field(*dialog, "answerId")->setText(field(*dialog, "requestId")->text());
    EXPECT_FALSE(okEnabled(*dialog));
    EXPECT_TRUE(dialog->problem().startsWith(QStringLiteral("The module cannot be used so:")))
        << dialog->problem().toStdString();
    field(*dialog, "requestId")->setText(QStringLiteral("0x1FE0009"));
    field(*dialog, "answerId")->setText(QStringLiteral("1ff0009"));
    ASSERT_TRUE(okEnabled(*dialog)) << dialog->problem().toStdString();
    dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();

    const connection::DeviceSettings after = saved();
    ASSERT_EQ(after.roModules.size(), 2u);
    const connection::RoModuleSettings* added = after.roModule(QStringLiteral("Relais Süd"));
    ASSERT_NE(added, nullptr);
    EXPECT_EQ(added->profile.ids, (ro::FrameIds{0x1FE0009, 0x1FF0009, true}));
    EXPECT_EQ(added->profile.outputs.count, 16) << "the simulator's layout is the starting point";
    EXPECT_NE(connection.devices().settings().roModule(QStringLiteral("Relais Süd")), nullptr)
        << "the next connection uses it";
    EXPECT_TRUE(panel->noteText().contains(QStringLiteral("next connection")));
}

TEST_F(DevicesEditingTest, EscapeLeavesTheModulesAsTheyWere) {
    RoModuleDialog* dialog = panel->editModule(QStringLiteral("RO 1"));
    ASSERT_NE(dialog, nullptr);
    field(*dialog, "moduleName")->setText(QStringLiteral("Umbenannt"));
    QTest::keyClick(dialog, Qt::Key_Escape);
    EXPECT_TRUE(saved().roModules.empty()) << "nothing was written";
    ASSERT_EQ(connection.devices().settings().roModules.size(), 1u);
    EXPECT_EQ(connection.devices().settings().roModules[0].profile.name, "RO 1");
}

TEST_F(DevicesEditingTest, AModuleIsRemovedFromTheSettings) {
    panel->removeModule(QStringLiteral("RO 1"));
    EXPECT_TRUE(connection.devices().settings().roModules.empty());
    EXPECT_TRUE(saved().roModules.empty());
    EXPECT_TRUE(saved().orc.on) << "the central stays";
}

TEST_F(DevicesEditingTest, ABindingMadeHereSwitchesTheRelayFromTheRailwayAndIsSaved) {
    ASSERT_TRUE(waitUntil([&] { return railwayDevices() && railways->railway()->accessory(2); }));
    BindingsDialog* dialog = panel->editBindings();
    ASSERT_NE(dialog, nullptr);
    dialog->accessoryChoice().setCurrentIndex(dialog->accessoryChoice().findData(qint64(2)));
    dialog->accessoryKind().setCurrentIndex(0); // RO relay
    dialog->accessorySource().setCurrentText(QStringLiteral("RO 1"));
    dialog->accessoryNumber().setValue(5);
    ASSERT_TRUE(dialog->addAccessory()) << dialog->problem().toStdString();
    EXPECT_EQ(dialog->accessoryTable().rowCount(), 1);
    EXPECT_EQ(dialog->accessoryTable().item(0, 1)->text(), QStringLiteral("relay 5 of “RO 1”"));
    dialog->accessoryKind().setCurrentIndex(1); // OpenRailCAN decoder output
    dialog->accessorySource().setCurrentText(QStringLiteral("no id"));
    EXPECT_FALSE(dialog->addAccessory());
    EXPECT_TRUE(dialog->problem().contains(QStringLiteral("is no bus id")));
    dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();

    EXPECT_TRUE(railwayDevices()->drives(2));
    railways->railway()->switchAccessory(2, 1);
    ASSERT_TRUE(waitUntil([&] { return module.relay(5); }));
    ASSERT_TRUE(waitUntil([&] {
        const model::Accessory* accessory = railways->railway()->accessory(2);
        return accessory->isPositionReported() && accessory->position() == 1;
    }));

    QSettings settings = stellwerkSettings();
    const model::DeviceBindings stored = model::DeviceBindings::load(settings);
    ASSERT_EQ(stored.accessories.size(), 1u);
    EXPECT_EQ(stored.accessories[0], (model::AccessoryBinding{2, model::RoRelay{QStringLiteral("RO 1"), 5}}));
}

} // namespace
} // namespace stellwerk::ui::test
