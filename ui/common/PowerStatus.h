#pragma once

#include <QPointer>
#include <QWidget>

class QLabel;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The track power as a lamp and a sentence (on, halted, off, not reported yet), as the station reported
// it; shown in the status bar and on the layout overview.
class PowerStatus final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PowerStatus)

public:
    explicit PowerStatus(QWidget* parent = nullptr);

    void setRailway(const model::Railway* railway);
    QString text() const;
    // The sentence for `railway`'s power (null: no station connected), in the current language.
    static QString powerText(const model::Railway* railway);

protected:
    void changeEvent(QEvent* event) override;

private:
    void refresh();

    QPointer<const model::Railway> m_railway;
    QLabel* m_lamp;
    QLabel* m_text;
};

} // namespace stellwerk::ui
