#pragma once

#include "model/Device.h"

#include <QWidget>
#include <cstdint>

class QComboBox;
class QDoubleSpinBox;
class QHBoxLayout;
class QLabel;
class QSlider;

namespace stellwerk::ui {

// One configuration channel of a device on the Status page: a drop-down for a list channel, a slider
// with a number field (range and unit from the description) for a number channel, and after a write
// whether the device accepted it. Shows the value the device reports, not the one last chosen.
class DeviceSettingEditor final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(DeviceSettingEditor)

public:
    enum class State { Idle, Writing, Accepted, Refused, NoAnswer };

    explicit DeviceSettingEditor(const model::DeviceSetting& setting, QWidget* parent = nullptr);

    std::uint8_t channel() const { return m_channel; }
    // Takes the value the device reported (unless the user is moving the slider).
    void setSetting(const model::DeviceSetting& setting);
    void setState(State state);
    void showResult(model::SettingResult result);
    State state() const { return m_state; }
    QString stateText() const;

    QComboBox* list() const { return m_list; }
    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* number() const { return m_number; }

signals:
    // The user chose a value (list index or raw number) different from the device's.
    void valueChosen(quint8 channel, quint16 value);

protected:
    void changeEvent(QEvent* event) override;

private:
    void buildList(const model::DeviceSetting& setting);
    void buildNumber(const model::DeviceSetting& setting);
    void choose(std::uint16_t value);
    void showValue(std::uint16_t value);
    void retranslate();

    std::uint8_t m_channel = 0;
    std::uint16_t m_reported = 0; // what the device last said
    std::uint16_t m_chosen = 0;   // what the user last chose
    model::DeviceSetting m_setting;
    State m_state = State::Idle;
    QComboBox* m_list = nullptr;
    QSlider* m_slider = nullptr;
    QDoubleSpinBox* m_number = nullptr;
    QHBoxLayout* m_row = nullptr;
    QLabel* m_result = nullptr;
};

} // namespace stellwerk::ui
