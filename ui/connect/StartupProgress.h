#pragma once

#include "connection/StationConnection.h"

#include <QPointer>
#include <QProgressBar>

namespace stellwerk::ui {

// A progress bar in the status bar while a station's configuration loads: the file being downloaded with
// its bytes of the announced total, or the start-up step; hidden at any other time.
class StartupProgress final : public QProgressBar {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(StartupProgress)

public:
    explicit StartupProgress(QWidget* parent = nullptr);

    void setConnection(const connection::StationConnection* station);
    // "lokomotive.cs2: 12.4 of 45.0 kB (file 1 of 8)", or the step.
    static QString describe(const connection::LoadingProgress& progress);

protected:
    void changeEvent(QEvent* event) override;

private:
    void refresh();

    QPointer<const connection::StationConnection> m_connection;
};

} // namespace stellwerk::ui
