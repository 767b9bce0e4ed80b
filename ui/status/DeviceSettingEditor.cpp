#include "status/DeviceSettingEditor.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

namespace stellwerk::ui {

DeviceSettingEditor::DeviceSettingEditor(const model::DeviceSetting& setting, QWidget* parent)
    : QWidget(parent), m_channel(setting.channel()), m_reported(setting.value()), m_setting(setting) {
    setObjectName(QStringLiteral("deviceSetting%1").arg(setting.channel()));
    // The choice on one line, what the device answered under it: a side panel is narrow.
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(2);
    m_row = new QHBoxLayout;
    column->addLayout(m_row);
    if (setting.isList())
        buildList(setting);
    else
        buildNumber(setting);
    m_result = new QLabel(this);
    column->addWidget(m_result);
    showValue(setting.value());
    retranslate();
}

void DeviceSettingEditor::buildList(const model::DeviceSetting& setting) {
    m_list = new QComboBox(this);
    m_list->addItems(setting.options());
    m_list->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_row->addWidget(m_list);
    connect(m_list, &QComboBox::activated, this, [this](int index) { choose(std::uint16_t(index)); });
}

// The slider works in the device's raw steps, the number field in the unit (0.500 .. 4.500 A).
void DeviceSettingEditor::buildNumber(const model::DeviceSetting& setting) {
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setRange(setting.minimum(), setting.maximum());
    m_slider->setPageStep(std::max(1, (setting.maximum() - setting.minimum()) / 10));
    m_slider->setMinimumWidth(100);
    m_number = new QDoubleSpinBox(this);
    m_number->setDecimals(setting.decimals());
    m_number->setRange(setting.scaled(setting.minimum()), setting.scaled(setting.maximum()));
    m_number->setSingleStep(
        std::abs(setting.scaled(std::uint16_t(setting.minimum() + 1)) - setting.scaled(setting.minimum())));
    if (!setting.unit().isEmpty())
        m_number->setSuffix(QLatin1Char(' ') + setting.unit());
    m_row->addWidget(m_slider, 1);
    m_row->addWidget(m_number);
    connect(m_slider, &QSlider::valueChanged, this, [this](int raw) {
        const QSignalBlocker blocker(m_number);
        m_number->setValue(m_setting.scaled(std::uint16_t(raw)));
        if (!m_slider->isSliderDown())
            choose(std::uint16_t(raw)); // keyboard, wheel or a click on the groove
    });
    connect(m_slider, &QSlider::sliderReleased, this, [this] { choose(std::uint16_t(m_slider->value())); });
    connect(m_number, &QDoubleSpinBox::editingFinished, this,
            [this] { choose(m_setting.rawFor(m_number->value())); });
}

void DeviceSettingEditor::choose(std::uint16_t value) {
    if (value == m_reported)
        return; // e.g. the number field losing the focus unchanged
    m_chosen = value;
    setState(State::Writing);
    emit valueChosen(m_channel, value);
}

void DeviceSettingEditor::setSetting(const model::DeviceSetting& setting) {
    m_setting = setting;
    const bool changed = m_reported != setting.value();
    m_reported = setting.value();
    // While a write is under way, or until the device reports the accepted value, the choice stays.
    const bool waiting = m_state == State::Writing || (m_state == State::Accepted && !changed);
    if (!(m_slider && m_slider->isSliderDown()) && !waiting)
        showValue(setting.value());
}

void DeviceSettingEditor::showValue(std::uint16_t value) {
    if (m_list) {
        const QSignalBlocker blocker(m_list);
        m_list->setCurrentIndex(value);
    }
    if (m_slider) {
        const QSignalBlocker sliderBlocker(m_slider);
        const QSignalBlocker numberBlocker(m_number);
        m_slider->setValue(value);
        m_number->setValue(m_setting.scaled(value));
    }
}

void DeviceSettingEditor::setState(State state) {
    m_state = state;
    retranslate();
}

void DeviceSettingEditor::showResult(model::SettingResult result) {
    switch (result) {
    case model::SettingResult::Accepted:
        setState(State::Accepted);
        showValue(m_chosen);
        break;
    case model::SettingResult::Refused:
        setState(State::Refused);
        showValue(m_reported); // the device keeps its value
        break;
    case model::SettingResult::NoAnswer:
        setState(State::NoAnswer);
        showValue(m_reported);
        break;
    }
}

QString DeviceSettingEditor::stateText() const {
    switch (m_state) {
    case State::Idle:
        return {};
    case State::Writing:
        return tr("writing…");
    case State::Accepted:
        return tr("accepted ✓");
    case State::Refused:
        return tr("refused ✗");
    case State::NoAnswer:
        return tr("no answer ✗");
    }
    return {};
}

void DeviceSettingEditor::retranslate() {
    m_result->setText(stateText());
    m_result->setVisible(!m_result->text().isEmpty());
    const bool bad = m_state == State::Refused || m_state == State::NoAnswer;
    const bool good = m_state == State::Accepted;
    m_result->setStyleSheet(bad    ? QStringLiteral("color: #d03636; font-weight: bold;")
                            : good ? QStringLiteral("color: #2ea04e; font-weight: bold;")
                                   : QString());
    switch (m_state) {
    case State::Refused:
        m_result->setToolTip(tr("The device refused the value and keeps its setting."));
        break;
    case State::NoAnswer:
        m_result->setToolTip(tr("The device did not answer; its setting is unknown. Try again."));
        break;
    default:
        m_result->setToolTip(QString());
    }
}

void DeviceSettingEditor::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
