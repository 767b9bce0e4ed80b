#pragma once

#include "connection/StationConnection.h"

#include <QWidget>

class QLabel;

namespace stellwerk::ui {

// The station line in the status bar: which station, and whether it is connecting, loading its
// configuration (step and file), ready (what it holds), silent or failed. It shows the connection's
// user-level state only and never looks at the protocol.
class ConnectionStatus final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConnectionStatus)

public:
    explicit ConnectionStatus(QWidget* parent = nullptr);

    // Follows `connection` from now on (null: "No station connected"). It must outlive this widget or
    // be replaced before it goes.
    void setConnection(const connection::StationConnection* station);
    QString text() const;

    // The station as a person calls it, in the current language.
    static QString describe(const connection::StationEndpoint& endpoint);
    // What to try when the station cannot be reached, for its kind of connection.
    static QString advice(const connection::StationEndpoint& endpoint);
    // The whole line for a connection in its current state.
    static QString statusText(const connection::StationConnection* station);

protected:
    void changeEvent(QEvent* event) override;

private:
    static QString loadingText(const connection::LoadingProgress& progress);
    static QString readyText(const connection::StationCounts& counts);
    void refresh();

    const connection::StationConnection* m_connection = nullptr;
    QLabel* m_lamp = nullptr;
    QLabel* m_text = nullptr;
};

} // namespace stellwerk::ui
