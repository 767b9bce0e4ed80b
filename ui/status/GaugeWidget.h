#pragma once

#include "model/Device.h"

#include <QString>
#include <QWidget>
#include <array>
#include <optional>

namespace stellwerk::ui {

// One device reading as a round instrument, like the CS2's own system page: the scale from the
// description with its coloured zones, a needle for the value and the value in the unit below, so that
// a current creeping into the red is seen at a glance. An old value (no answer) is drawn grey.
class GaugeWidget final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(GaugeWidget)

public:
    explicit GaugeWidget(QWidget* parent = nullptr);

    // Takes scale, zones, unit, decimals and the current value of `channel`.
    void setChannel(const model::StatusChannel& channel);
    void setTitle(const QString& title);
    QString title() const { return m_title; }
    // Marks the gauge after the device reported an overload on it, until cleared.
    void setOverloaded(bool overloaded);
    bool overloaded() const { return m_overloaded; }

    std::optional<double> value() const { return m_value; }
    bool stale() const { return m_stale; }
    int decimals() const { return m_decimals; }
    QString unit() const { return m_unit; }
    double minimum() const { return m_minimum; }
    double maximum() const { return m_maximum; }
    // "2.345 A" in the widget's locale; "–" before the first reading.
    QString valueText() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    // The angle (degrees, Qt's counter-clockwise from 3 o'clock) of `value` on the 270° scale.
    double angleOf(double value) const;
    void paintZones(QPainter& painter, const QRectF& dial) const;
    void paintScale(QPainter& painter, const QRectF& dial) const;
    void paintNeedle(QPainter& painter, const QRectF& dial) const;
    void paintTexts(QPainter& painter, const QRectF& dial) const;
    QString number(double value, int decimals) const;

    QString m_title;
    QString m_unit;
    double m_minimum = 0;
    double m_maximum = 1;
    int m_decimals = 0;
    std::array<model::StatusChannel::Zone, 4> m_zones{};
    std::optional<double> m_value;
    bool m_stale = false;
    bool m_overloaded = false;
};

} // namespace stellwerk::ui
