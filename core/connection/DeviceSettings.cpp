#include "connection/DeviceSettings.h"

#include <QSettings>
#include <algorithm>

namespace stellwerk::connection {

namespace {

// Every key of the device settings, in one place.
const QString group = QStringLiteral("devices");
const QString orcOnKey = QStringLiteral("orc/on");
const QString orcBusKey = QStringLiteral("orc/bus");
const QString orcBusIdKey = QStringLiteral("orc/busId");
const QString orcUidKey = QStringLiteral("orc/uid");
const QString roAnswerTimeoutKey = QStringLiteral("ro/answerTimeoutMs");
const QString roModulesKey = QStringLiteral("roModules");
const QString nameKey = QStringLiteral("name");
const QString requestKey = QStringLiteral("request");
const QString answerKey = QStringLiteral("answer");
const QString extendedKey = QStringLiteral("extended");
const QString busKey = QStringLiteral("bus");
const QString pollKey = QStringLiteral("pollMs");
const QString outputsKey = QStringLiteral("outputs");
const QString inputsKey = QStringLiteral("inputs");
const QString flagsKey = QStringLiteral("changeFlags");
const QString readSizeKey = QStringLiteral("readRequestSize");

// A register block as "address,width,count" (width 1 bit .. 4 long, as the codec numbers it).
QString blockText(const ro::RegisterBlock& block) {
    return QStringLiteral("%1,%2,%3").arg(block.address).arg(int(block.width)).arg(block.count);
}

std::optional<ro::RegisterBlock> blockOf(const QString& text) {
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() != 3)
        return std::nullopt;
    bool ok[3] = {};
    const uint address = parts[0].toUInt(&ok[0]);
    const uint width = parts[1].toUInt(&ok[1]);
    const uint count = parts[2].toUInt(&ok[2]);
    if (!ok[0] || !ok[1] || !ok[2] || address > 0xFFFF || width < 1 || width > 4 || count > 32)
        return std::nullopt;
    return ro::RegisterBlock{std::uint16_t(address), ro::Width(width), std::uint8_t(count)};
}

void saveModule(QSettings& settings, const RoModuleSettings& module) {
    const ro::RoProfile& profile = module.profile;
    settings.setValue(nameKey, QString::fromStdString(profile.name));
    settings.setValue(requestKey, profile.ids.request);
    settings.setValue(answerKey, profile.ids.answer);
    settings.setValue(extendedKey, profile.ids.extended);
    settings.setValue(busKey, module.bus);
    settings.setValue(pollKey, qint64(module.pollPeriod.count()));
    settings.setValue(outputsKey, blockText(profile.outputs));
    settings.setValue(inputsKey, blockText(profile.inputs));
    settings.setValue(flagsKey, profile.changeFlags ? blockText(*profile.changeFlags) : QString());
    settings.setValue(readSizeKey, int(profile.readRequestSize));
}

std::optional<RoModuleSettings> loadModule(const QSettings& settings) {
    RoModuleSettings module;
    ro::RoProfile& profile = module.profile;
    profile.name = settings.value(nameKey).toString().toStdString();
    profile.ids = {settings.value(requestKey).toUInt(), settings.value(answerKey).toUInt(),
                   settings.value(extendedKey, true).toBool()};
    module.bus = std::max(0, settings.value(busKey).toInt());
    module.pollPeriod =
        std::chrono::milliseconds(std::max<qint64>(100, settings.value(pollKey, 250).toLongLong()));
    const auto outputs = blockOf(settings.value(outputsKey).toString());
    const auto inputs = blockOf(settings.value(inputsKey).toString());
    if (!outputs || !inputs || profile.name.empty())
        return std::nullopt;
    profile.outputs = *outputs;
    profile.inputs = *inputs;
    profile.changeFlags = blockOf(settings.value(flagsKey).toString());
    profile.readRequestSize =
        settings.value(readSizeKey, 8).toInt() == 4 ? ro::ReadRequestSize::Four : ro::ReadRequestSize::Eight;
    return module;
}

} // namespace

const RoModuleSettings* DeviceSettings::roModule(const QString& name) const {
    const std::string wanted = name.toStdString();
    const auto found = std::find_if(roModules.begin(), roModules.end(), [&](const RoModuleSettings& module) {
        return module.profile.name == wanted;
    });
    return found == roModules.end() ? nullptr : &*found;
}

bool DeviceSettings::usesBus(int bus) const {
    return (orc.on && orc.bus == bus) || std::any_of(roModules.begin(), roModules.end(),
                                                     [bus](const auto& module) { return module.bus == bus; });
}

int DeviceSettings::highestBus() const {
    int highest = orc.on ? orc.bus : -1;
    for (const RoModuleSettings& module : roModules)
        highest = std::max(highest, module.bus);
    return highest;
}

DeviceSettings DeviceSettings::embeddedDemo() {
    DeviceSettings demo;
    demo.orc.on = true;
    demo.orc.bus = 1;
    RoModuleSettings module;
    module.profile = ro::RoProfile::simulator(1);
    module.profile.name = "Demo RO";
    module.bus = 1;
    demo.roModules.push_back(module);
    return demo;
}

DeviceSettings DeviceSettings::load(QSettings& settings) {
    DeviceSettings devices;
    settings.beginGroup(group);
    devices.orc.on = settings.value(orcOnKey, false).toBool();
    devices.orc.bus = std::max(0, settings.value(orcBusKey, 0).toInt());
    devices.orc.session.busId = std::uint16_t(settings.value(orcBusIdKey, 0).toUInt());
    devices.orc.session.uid = settings.value(orcUidKey, 0).toUInt();
    devices.roTiming.answerTimeout =
        std::chrono::milliseconds(std::max(10, settings.value(roAnswerTimeoutKey, 100).toInt()));
    const int count = settings.beginReadArray(roModulesKey);
    for (int index = 0; index < count; ++index) {
        settings.setArrayIndex(index);
        if (auto module = loadModule(settings))
            devices.roModules.push_back(std::move(*module));
    }
    settings.endArray();
    settings.endGroup();
    return devices;
}

void DeviceSettings::save(QSettings& settings) const {
    settings.beginGroup(group);
    settings.remove(QString()); // the group's old modules, so that fewer ones leave none behind
    settings.setValue(orcOnKey, orc.on);
    settings.setValue(orcBusKey, orc.bus);
    settings.setValue(orcBusIdKey, orc.session.busId);
    settings.setValue(orcUidKey, orc.session.uid);
    settings.setValue(roAnswerTimeoutKey, qint64(roTiming.answerTimeout.count()));
    settings.beginWriteArray(roModulesKey, int(roModules.size()));
    for (int index = 0; index < int(roModules.size()); ++index) {
        settings.setArrayIndex(index);
        saveModule(settings, roModules[std::size_t(index)]);
    }
    settings.endArray();
    settings.endGroup();
}

} // namespace stellwerk::connection
