#pragma once

#include <QList>
#include <QPointer>
#include <QString>
#include <QWidget>
#include <cstdint>
#include <map>
#include <vector>

class QGroupBox;
class QLabel;
class QVBoxLayout;

namespace stellwerk::model {
class Device;
class Railway;
} // namespace stellwerk::model

namespace stellwerk::ui {

class DeviceSettingEditor;
class GaugeWidget;

// The Status page: a group per device that describes its readings, one gauge per reading, and a red
// banner when a device reports an overload. The readings are asked for only while the page is visible.
class StatusPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(StatusPanel)

public:
    explicit StatusPanel(QWidget* parent = nullptr);
    ~StatusPanel() override;

    // The railway whose devices the page shows (null: none).
    void setRailway(model::Railway* railway);

    // The gauges of a device in the description's order; empty for an unknown device.
    QList<GaugeWidget*> gauges(std::uint32_t device) const;
    QGroupBox* deviceGroup(std::uint32_t device) const;
    // The editors of a device's configuration channels in the description's order.
    QList<DeviceSettingEditor*> settingEditors(std::uint32_t device) const;
    // The overload banner's text; empty while it is hidden.
    QString overloadText() const;

    // A reading's name in the user's language ("HGL" -> "Track current (main)"); unknown names as given.
    static QString measurementName(const QString& name);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    struct DeviceGauges {
        QGroupBox* group = nullptr;
        std::vector<std::uint8_t> channels;
        QList<GaugeWidget*> gauges;
        QLabel* settingsTitle = nullptr;
        QList<QLabel*> settingLabels;
        QList<DeviceSettingEditor*> settings;
    };

    void rebuild();
    void devicesChanged(const QList<quint32>& uids);
    void updateDevice(std::uint32_t uid);
    void addDevice(std::uint32_t uid);
    void addSettings(const model::Device& device, DeviceGauges& entry);
    void showSettingResult(quint32 uid, quint8 channel, int result);
    static bool shows(const model::Device* device);
    void showOverload(quint32 device, quint8 channel);
    void clearOverload();
    void retranslate();
    void updatePolling();

    QPointer<model::Railway> m_railway;
    QLabel* m_overloadBanner = nullptr;
    QLabel* m_emptyText = nullptr;
    QVBoxLayout* m_devicesLayout = nullptr;
    std::map<std::uint32_t, DeviceGauges> m_devices;
    // The overloaded reading, to name it again after a language change.
    bool m_overload = false;
    std::uint32_t m_overloadDevice = 0;
    std::uint8_t m_overloadChannel = 0;
};

} // namespace stellwerk::ui
