#pragma once

#include <QPointer>
#include <QWidget>

class QLabel;
class QTimer;

namespace stellwerk::connection {
class ConnectionBuses;
}

namespace stellwerk::ui {

// The frame counters of the status bar: frames received and sent on the station's transport, read twice
// a second (never per frame, so that a flooded bus costs the window nothing).
class TrafficStatus final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TrafficStatus)

public:
    static constexpr int RefreshMs = 500;

    explicit TrafficStatus(QWidget* parent = nullptr);

    // Counts the frames of the station's bus among `buses` (null: none).
    void setBuses(const connection::ConnectionBuses* buses);
    QString text() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void refresh();

    QPointer<const connection::ConnectionBuses> m_buses;
    QLabel* m_text;
    QTimer* m_timer;
};

} // namespace stellwerk::ui
