#pragma once

#include <QList>
#include <QWidget>
#include <cstdint>
#include <optional>

class QGridLayout;
class QToolButton;

namespace stellwerk::ui {

// A device's relays or inputs as numbered lamps (1..n, eight to a row): each on, off or "not reported".
// Relay lamps are buttons that ask for the other state and show it only once the device confirmed it;
// until then the lamp says it is waiting. Input lamps only show.
class SignalGrid final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(SignalGrid)

public:
    enum class Kind : std::uint8_t { Switches, Lamps };

    explicit SignalGrid(Kind kind, QWidget* parent = nullptr);

    void setCount(int count);
    int count() const { return int(m_cells.size()); }
    // Bit n-1 is number n; nullopt: the device has not reported them (shown grey, not switchable).
    void setStates(std::optional<std::uint32_t> states);
    // Whether switching is possible now (the device answers); lamps ignore it.
    void setSwitchable(bool switchable);
    // Every number asked for and not yet confirmed is no longer waited for (the device refused it).
    void stopWaiting();

    std::optional<bool> state(int number) const;
    bool isWaiting(int number) const;
    QToolButton* cell(int number) const;

signals:
    void switchRequested(int number, bool on);

private:
    void clicked(int number);
    void paintCell(int number);

    Kind m_kind;
    QGridLayout* m_grid;
    QList<QToolButton*> m_cells;
    std::optional<std::uint32_t> m_states;
    std::uint32_t m_waiting = 0;
    bool m_switchable = false;
};

} // namespace stellwerk::ui
