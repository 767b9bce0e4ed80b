#pragma once

#include "station/StationUpdates.h"

#include <QPointer>
#include <QToolButton>
#include <optional>

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The large power key of the toolbar, in one of three looks that cannot be mistaken for each other: a red
// STOP while the station reports track power on; a dark red "TRACK POWER OFF" (or "TRAINS HALTED") after a
// stop, which switches the power on again; and a grey STOP while the power is not reported (the station
// is silent, reconnecting, or has not said yet), which still stops. It only asks the railway; what it
// shows is what the station reported. It keeps the width of its widest look, so that nothing beside it
// moves when the power changes.
class StopGoButton final : public QToolButton {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(StopGoButton)

public:
    enum class Look { Stop, PowerOff, Halted, NotReported };
    Q_ENUM(Look)

    explicit StopGoButton(QWidget* parent = nullptr);

    // The railway to stop and start (null: none, the button is disabled).
    void setRailway(model::Railway* railway);
    // STOP for the whole layout, whatever the button shows.
    void stopEverything();
    // What a click does now: true when it stops.
    bool stops() const;
    Look look() const;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void changeEvent(QEvent* event) override;

private:
    static QString textOf(Look look);
    void press();
    void refresh();

    QPointer<model::Railway> m_railway;
};

} // namespace stellwerk::ui
