#pragma once

#include "station/StationUpdates.h"

#include <QPointer>
#include <QToolButton>
#include <optional>

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The large STOP / GO key of the toolbar: red STOP while the track has power (or its state is not known
// yet), green GO after a stop. It only asks the railway; what it shows is what the station reported.
class StopGoButton final : public QToolButton {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(StopGoButton)

public:
    explicit StopGoButton(QWidget* parent = nullptr);

    // The railway to stop and start (null: none, the button is disabled).
    void setRailway(model::Railway* railway);
    // STOP for the whole layout, whatever the button shows.
    void stopEverything();
    // What a click does now: true when it stops.
    bool stops() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void press();
    void refresh();

    QPointer<model::Railway> m_railway;
};

} // namespace stellwerk::ui
