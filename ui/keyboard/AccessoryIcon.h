#pragma once

#include <QColor>
#include <QCoreApplication>
#include <QList>
#include <QRectF>
#include <QString>

class QPainter;
class QPalette;

namespace stellwerk::ui {

// Our own vector drawings of the keyboard's article types (turnouts, double slips, signals,
// uncouplers, lamps, turntables), each drawn in the position it stands in, so that a key on the
// turnout panel shows at a glance which way a turnout lies or what a signal shows.
class AccessoryIcon final {
    Q_DECLARE_TR_FUNCTIONS(AccessoryIcon)

public:
    enum class Kind {
        Plain, // a keyboard number without an article: a red and a green lamp
        LeftTurnout,
        RightTurnout,
        YTurnout,
        ThreeWayTurnout,
        DoubleSlip,
        DoubleSlipTwoDrives,
        LightSignal,
        LightSignalHp02, // Hp0/Hp2 only: position 1 shows Hp2
        Semaphore,
        SemaphoreHp02,
        ShuntSignal,
        Uncoupler,
        Lamp,
        Output,
        Turntable,
        TransferTable,
    };

    // The drawing for a magnetartikel.cs2 `.typ` (unknown types are drawn as Lamp).
    static Kind kindOf(const QString& type);
    // Draws `kind` in `position` (-1: not known) into `box`, in the palette's colours.
    static void paint(QPainter& painter, const QRectF& box, Kind kind, int position, const QPalette& palette);
    // What a position means for the user: "Straight", "Hp0", "Track 5" ...
    static QString positionName(Kind kind, int position);
    // The colour of a position's button: red for 0, green for 1, yellow and white for the others.
    static QColor positionColour(int position);

private:
    static void paintTurnout(QPainter& painter, Kind kind, int position, const QPalette& palette);
    static void paintDoubleSlip(QPainter& painter, Kind kind, int position, const QPalette& palette);
    static void paintLightSignal(QPainter& painter, Kind kind, int position, const QPalette& palette);
    static void paintSemaphore(QPainter& painter, int aspect, const QPalette& palette);
    static void paintUncoupler(QPainter& painter, int position, const QPalette& palette);
    static void paintLamps(QPainter& painter, Kind kind, int position, const QPalette& palette);
    static void paintTurntable(QPainter& painter, Kind kind, int position, const QPalette& palette);
};

} // namespace stellwerk::ui
