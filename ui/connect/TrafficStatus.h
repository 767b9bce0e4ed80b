#pragma once

#include <QPointer>
#include <QWidget>

class QLabel;
class QTimer;

namespace stellwerk::connection {
class StationConnection;
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

    void setConnection(const connection::StationConnection* station);
    QString text() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void refresh();

    QPointer<const connection::StationConnection> m_connection;
    QLabel* m_text;
    QTimer* m_timer;
};

} // namespace stellwerk::ui
