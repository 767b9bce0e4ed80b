#include "status/StatusPanel.h"

#include "common/WrappingGrid.h"
#include "model/Railway.h"
#include "status/DeviceSettingEditor.h"
#include "status/GaugeWidget.h"

#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace stellwerk::ui {

StatusPanel::StatusPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("statusPanel"));
    auto* layout = new QVBoxLayout(this);
    m_overloadBanner = new QLabel(this);
    m_overloadBanner->setObjectName(QStringLiteral("overloadBanner"));
    m_overloadBanner->setWordWrap(true);
    m_overloadBanner->setStyleSheet(
        QStringLiteral("QLabel { background: #c82c2c; color: white; font-weight: bold;"
                       " padding: 10px; border-radius: 4px; }"));
    m_overloadBanner->hide();
    layout->addWidget(m_overloadBanner);

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* devices = new QWidget(scroll);
    m_devicesLayout = new QVBoxLayout(devices);
    m_emptyText = new QLabel(devices);
    m_emptyText->setAlignment(Qt::AlignCenter);
    m_emptyText->setEnabled(false);
    m_devicesLayout->addWidget(m_emptyText);
    m_devicesLayout->addStretch(1);
    scroll->setWidget(devices);
    layout->addWidget(scroll);
    retranslate();
}

StatusPanel::~StatusPanel() {
    if (m_railway)
        m_railway->readings().setActive(true); // the poller's default for whoever looks next
}

void StatusPanel::setRailway(model::Railway* railway) {
    if (m_railway) {
        disconnect(m_railway, nullptr, this, nullptr);
        m_railway->readings().setActive(true);
    }
    m_railway = railway;
    clearOverload();
    if (m_railway) {
        connect(m_railway, &model::Railway::devicesChanged, this, &StatusPanel::devicesChanged);
        connect(m_railway, &model::Railway::loaded, this, &StatusPanel::rebuild);
        connect(m_railway, &model::Railway::overloaded, this, &StatusPanel::showOverload);
        connect(m_railway, &model::Railway::deviceConfigured, this,
                [this](quint32 uid, quint8 channel, model::SettingResult result) {
                    showSettingResult(uid, channel, int(result));
                });
        connect(m_railway, &model::Railway::powerChanged, this, [this](station::PowerState state) {
            if (state == station::PowerState::Running)
                clearOverload();
        });
        connect(m_railway, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    rebuild();
    updatePolling();
}

QList<GaugeWidget*> StatusPanel::gauges(std::uint32_t device) const {
    const auto it = m_devices.find(device);
    return it == m_devices.end() ? QList<GaugeWidget*>() : it->second.gauges;
}

QGroupBox* StatusPanel::deviceGroup(std::uint32_t device) const {
    const auto it = m_devices.find(device);
    return it == m_devices.end() ? nullptr : it->second.group;
}

QList<DeviceSettingEditor*> StatusPanel::settingEditors(std::uint32_t device) const {
    const auto it = m_devices.find(device);
    return it == m_devices.end() ? QList<DeviceSettingEditor*>() : it->second.settings;
}

bool StatusPanel::shows(const model::Device* device) {
    return device && (!device->channels().empty() || !device->settings().empty());
}

QString StatusPanel::overloadText() const {
    return m_overloadBanner->isHidden() ? QString() : m_overloadBanner->text();
}

QString StatusPanel::measurementName(const QString& name) {
    if (name == QLatin1String("HGL"))
        return tr("Track current (main)");
    if (name == QLatin1String("PGL"))
        return tr("Track current (programming)");
    if (name == QLatin1String("TRACK"))
        return tr("Track current");
    if (name == QLatin1String("VOLT"))
        return tr("Voltage");
    if (name == QLatin1String("TEMP"))
        return tr("Temperature");
    return name;
}

void StatusPanel::rebuild() {
    for (auto& [uid, device] : m_devices)
        delete device.group;
    m_devices.clear();
    if (m_railway)
        for (const model::Device& device : m_railway->state().devices().items())
            addDevice(device.uid());
    m_emptyText->setVisible(m_devices.empty());
}

void StatusPanel::addDevice(std::uint32_t uid) {
    const model::Device* device = m_railway->device(uid);
    if (!shows(device))
        return;
    DeviceGauges entry;
    entry.group = new QGroupBox(device->name(), m_devicesLayout->parentWidget());
    entry.group->setToolTip(
        device->article().isEmpty()
            ? device->typeName()
            : tr("%1, article %2, version %3").arg(device->typeName(), device->article(), device->version()));
    auto* layout = new QVBoxLayout(entry.group);
    // The gauges wrap into as many columns as the panel's width holds.
    auto* gauges = new WrappingGrid(entry.group);
    layout->addWidget(gauges);
    for (const model::StatusChannel& channel : device->channels()) {
        auto* gauge = new GaugeWidget(gauges);
        gauge->setTitle(measurementName(channel.name()));
        gauge->setChannel(channel);
        gauges->add(gauge);
        entry.gauges.push_back(gauge);
        entry.channels.push_back(channel.channel());
    }
    addSettings(*device, entry);
    // Before the stretch, in the order the devices answered.
    m_devicesLayout->insertWidget(m_devicesLayout->count() - 1, entry.group);
    m_devices.emplace(uid, std::move(entry));
}

// Below the gauges: one row per configuration channel, its title and its editor.
void StatusPanel::addSettings(const model::Device& device, DeviceGauges& entry) {
    if (device.settings().empty())
        return;
    auto* layout = static_cast<QVBoxLayout*>(entry.group->layout());
    entry.settingsTitle = new QLabel(entry.group);
    QFont bold = entry.settingsTitle->font();
    bold.setBold(true);
    entry.settingsTitle->setFont(bold);
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    form->setRowWrapPolicy(QFormLayout::WrapAllRows); // the titles are long, the panel narrow
    for (const model::DeviceSetting& setting : device.settings()) {
        auto* label = new QLabel(setting.title(), entry.group);
        auto* editor = new DeviceSettingEditor(setting, entry.group);
        connect(editor, &DeviceSettingEditor::valueChosen, this,
                [this, uid = device.uid()](quint8 channel, quint16 value) {
                    if (m_railway)
                        m_railway->configureDevice(uid, channel, value);
                });
        form->addRow(label, editor);
        entry.settingLabels.push_back(label);
        entry.settings.push_back(editor);
    }
    layout->addWidget(entry.settingsTitle);
    layout->addLayout(form);
    entry.settingsTitle->setText(tr("Settings"));
}

void StatusPanel::showSettingResult(quint32 uid, quint8 channel, int result) {
    for (DeviceSettingEditor* editor : settingEditors(uid))
        if (editor->channel() == channel)
            editor->showResult(model::SettingResult(result));
}

void StatusPanel::devicesChanged(const QList<quint32>& uids) {
    if (!m_railway)
        return;
    bool added = false;
    for (const quint32 uid : uids) {
        if (m_devices.contains(uid))
            updateDevice(uid);
        else if (shows(m_railway->device(uid)))
            added = true;
    }
    if (added)
        rebuild();
}

void StatusPanel::updateDevice(std::uint32_t uid) {
    const model::Device* device = m_railway->device(uid);
    DeviceGauges& entry = m_devices.at(uid);
    if (!device || device->channels().size() != entry.channels.size() ||
        device->settings().size() != std::size_t(entry.settings.size())) {
        rebuild();
        return;
    }
    for (DeviceSettingEditor* editor : entry.settings)
        if (const model::DeviceSetting* setting = device->setting(editor->channel()))
            editor->setSetting(*setting);
    for (qsizetype i = 0; i < entry.gauges.size(); ++i)
        if (const model::StatusChannel* channel = device->channel(entry.channels[std::size_t(i)]))
            entry.gauges[i]->setChannel(*channel);
}

void StatusPanel::showOverload(quint32 device, quint8 channel) {
    m_overload = true;
    m_overloadDevice = device;
    m_overloadChannel = channel;
    for (auto& [uid, entry] : m_devices)
        for (qsizetype i = 0; i < entry.gauges.size(); ++i)
            entry.gauges[i]->setOverloaded(uid == device && entry.channels[std::size_t(i)] == channel);
    retranslate();
    m_overloadBanner->show();
}

void StatusPanel::clearOverload() {
    m_overload = false;
    m_overloadBanner->hide();
    for (auto& [uid, entry] : m_devices)
        for (GaugeWidget* gauge : entry.gauges)
            gauge->setOverloaded(false);
}

void StatusPanel::retranslate() {
    m_emptyText->setText(tr("No device has described its readings yet."));
    for (auto& [uid, entry] : m_devices) {
        if (entry.settingsTitle)
            entry.settingsTitle->setText(tr("Settings"));
        const model::Device* device = m_railway ? m_railway->device(uid) : nullptr;
        for (qsizetype i = 0; i < entry.gauges.size() && device; ++i)
            if (const model::StatusChannel* channel = device->channel(entry.channels[std::size_t(i)]))
                entry.gauges[i]->setTitle(measurementName(channel->name()));
    }
    if (m_overload) {
        const model::Device* device = m_railway ? m_railway->device(m_overloadDevice) : nullptr;
        const model::StatusChannel* channel = device ? device->channel(m_overloadChannel) : nullptr;
        const QString where = device ? device->name() : tr("a device");
        const QString what =
            channel ? measurementName(channel->name()) : tr("channel %1").arg(m_overloadChannel);
        m_overloadBanner->setText(
            tr("Overload on %1 (%2): the track power is off. Look for a short circuit or "
               "a derailed train, then switch the power on again.")
                .arg(where, what));
    }
}

void StatusPanel::updatePolling() {
    if (m_railway)
        m_railway->readings().setActive(isVisible());
}

void StatusPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (m_railway)
        m_railway->readings().setActive(true);
}

void StatusPanel::hideEvent(QHideEvent* event) {
    QWidget::hideEvent(event);
    if (m_railway)
        m_railway->readings().setActive(false);
}

void StatusPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
