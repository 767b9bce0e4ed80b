#pragma once

#include <QObject>

namespace stellwerk::ui {

// Space and Escape stop the whole layout from anywhere in the application, whichever widget has the
// focus, as the STOP key of a CS2 does. Space is left to text fields while one is being typed in (a name
// with a space must stay possible); Escape always stops and is still passed on (a dialog closes too).
class EmergencyStopKeys final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(EmergencyStopKeys)

public:
    // Watches every key press of the application while it exists.
    explicit EmergencyStopKeys(QObject* parent = nullptr);
    ~EmergencyStopKeys() override;

signals:
    void stopRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
};

} // namespace stellwerk::ui
