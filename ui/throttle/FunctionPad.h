#pragma once

#include "model/Locomotive.h"

#include <QColor>
#include <QPointer>
#include <QWidget>
#include <cstdint>
#include <map>

class QGridLayout;
class QPalette;
class QToolButton;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// A throttle's function keys (F0-F31) for one locomotive: one button per function its file lists, with
// our icon for the function's kind or its number, acting as the file says (latching, momentary while
// held, or timed). Buttons show what the station confirmed; a command it did not acknowledge outlines
// the button in a warning colour until the user presses it again or the station acknowledges a command for
// that function. Greyed (state not reported), keys are paler than usable ones yet keep readable contrast.
class FunctionPad final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(FunctionPad)

public:
    static constexpr int Columns = 4;
    // Keys shown for a locomotive whose file lists no functions (one only seen on the bus).
    static constexpr int DefaultKeys = 16;

    // The colours of greyed keys (the state not reported) for off and on, text and drawings alike.
    struct Greyed {
        QColor offText;
        QColor offBackground;
        QColor onText;
        QColor onBackground;
    };
    static Greyed greyed(const QPalette& palette);

    explicit FunctionPad(QWidget* parent = nullptr);

    // Builds the keys of `loco` on `railway` (null: none).
    void setLocomotive(model::Railway* railway, std::uint32_t loco);
    // Shows the functions' confirmed states again.
    void refresh();
    // A function key pressed or released on the keyboard (or the button): acts by the function's trigger.
    void press(int function);
    void release(int function);

    void markUnacknowledged(int function, const QString& reason);
    void clearMark(int function);
    bool isMarked(int function) const { return m_marks.contains(function); }

    QToolButton* button(int function) const;
    // No keys: no locomotive, or one the railway does not know (yet).
    bool isEmpty() const { return m_keys.empty(); }
    void retranslate();

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Key {
        QToolButton* button = nullptr;
        model::LocomotiveFunction function;
    };

    const model::Locomotive* locomotive() const;
    void clear();
    void addKey(const model::LocomotiveFunction& function);
    void reserveRows();
    void updateKey(Key& key);
    void updateIcons();

    QPointer<model::Railway> m_railway;
    std::uint32_t m_loco = 0;
    QGridLayout* m_grid;
    std::map<int, Key> m_keys;
    std::map<int, QString> m_marks; // function -> why its last command failed
};

} // namespace stellwerk::ui
