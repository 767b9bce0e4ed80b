#pragma once

#include "model/Railway.h"

#include <QFrame>
#include <QPointer>
#include <QString>
#include <cstdint>
#include <map>

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QTimer;
class QToolButton;

namespace stellwerk::ui {

class FunctionPad;
class LocomotivePictureBook;
class SpeedScale;

// One throttle: drives one locomotive chosen from the station's list with a speed slider (0-100 %, the
// station's 0-1000) on a km/h scale, a direction button, an emergency stop for this locomotive and its
// function keys. Its big number shows only the speed the station confirmed (so other controllers' changes
// appear at once); the slider may lead it, and while its request waits a dashed outline and "Requested: …"
// say so. A control whose last command the station did not acknowledge is outlined in a warning colour,
// with the reason in its tooltip, until the user works that control again or the station acknowledges one
// of its commands. Changing the locomotive while it runs asks first.
// Keys while it has focus: Up/Down/+/- speed, PageUp/PageDown larger steps, R direction, 0-9 F0-F9,
// E emergency stop; Space and Escape are left to the window (STOP for the whole layout).
class ThrottleWidget final : public QFrame {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ThrottleWidget)

public:
    using Control = model::Railway::LocomotiveControl;

    static constexpr int SpeedStepPercent = 5;
    static constexpr int SpeedPageStepPercent = 25;

    explicit ThrottleWidget(QWidget* parent = nullptr);

    // The railway whose locomotives it drives (null: none).
    void setRailway(model::Railway* railway);
    // Drives `loco` (0: none). Kept while the railway does not know it yet, e.g. before it loaded.
    void setLocomotive(std::uint32_t loco);
    std::uint32_t locomotive() const { return m_loco; }
    // The number shown in the header, for the Alt+<number> focus key (0: none).
    void setNumber(int number);
    // Where the locomotive's picture comes from (null: the placeholder only).
    void setPictures(LocomotivePictureBook* pictures);

    // True while the control's last command was not acknowledged (function: its number, else ignored).
    bool isUnacknowledged(Control control, int function = -1) const;
    // The confirmed speed ("50 km/h", "40 %", "—").
    QString speedText() const;
    // The slider's speed while the station has not confirmed it ("Requested: 15 km/h"); empty otherwise.
    QString requestText() const;

    QComboBox* locomotiveChoice() const { return m_choice; }
    QSlider* speedSlider() const { return m_slider; }
    SpeedScale* speedScale() const { return m_scale; }
    QPushButton* directionButton() const { return m_direction; }
    QPushButton* emergencyStopButton() const { return m_stop; }
    QFrame* speedArea() const { return m_speedFrame; }
    QToolButton* closeButton() const { return m_close; }
    FunctionPad* functions() const { return m_functions; }
    QLabel* picture() const { return m_picture; }

signals:
    void locomotiveChosen(quint32 loco);
    void closeRequested();

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    QWidget* createHeader();
    QWidget* createSpeedArea();
    void fillChoice();
    void choose(int index);
    bool confirmChange(std::uint32_t wanted);
    void showLocomotive();
    void showPicture();
    void showState();
    void locomotivesChanged(const QList<quint32>& ids);
    void sliderMoved(int percent);
    void sendSpeed();
    void reverseDirection();
    void emergencyStop();
    void commandSent(quint32 loco, Control control, int function);
    void commandAcknowledged(quint32 loco, Control control, int function);
    void commandFailed(quint32 loco, Control control, int function, const QString& reason);
    void setMark(Control control, const QString& reason);
    void clearMark(Control control);
    QWidget* markedWidget(Control control) const;
    bool handlesKey(const QKeyEvent* event) const;
    bool drive(const QKeyEvent* event);
    const model::Locomotive* driven() const;
    QString speedWords(int speed) const;
    void retranslate();
    void retranslateSpeed();
    void retranslateMarks();

    QPointer<model::Railway> m_railway;
    std::uint32_t m_loco = 0;
    int m_number = 0;
    QComboBox* m_choice;
    QLabel* m_details;
    QLabel* m_picture;
    QPointer<LocomotivePictureBook> m_pictures;
    QLabel* m_numberLabel;
    QToolButton* m_close;
    QFrame* m_speedFrame;
    QSlider* m_slider;
    SpeedScale* m_scale;
    QLabel* m_speedText;
    QLabel* m_requestText;
    QPushButton* m_direction;
    QPushButton* m_stop;
    FunctionPad* m_functions;
    QTimer* m_sendTimer;
    int m_wantedSpeed = -1; // 0..1000 waiting for the send timer; -1: none
    int m_speedInFlight = 0;
    std::map<Control, QString> m_marks; // speed, direction, emergency stop -> why they failed
};

} // namespace stellwerk::ui
