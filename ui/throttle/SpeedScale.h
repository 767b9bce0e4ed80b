#pragma once

#include <QWidget>

namespace stellwerk::ui {

// The speedometer scale beside a throttle's slider: km/h marks from 0 to the locomotive's `.tachomax`,
// or percent marks when the file gives no top speed.
class SpeedScale final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(SpeedScale)

public:
    explicit SpeedScale(QWidget* parent = nullptr);

    // The top of the scale in km/h; 0 shows percent.
    void setTachoMax(int kmh);
    int tachoMax() const { return m_tachoMax; }
    // The text of each mark, bottom to top ("0", "40", ... "160 km/h").
    QStringList markTexts() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    int step() const;

    int m_tachoMax = 0;
};

} // namespace stellwerk::ui
