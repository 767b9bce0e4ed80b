#include "connect/StartupProgress.h"

#include "connect/ConnectionStatus.h"

#include <QEvent>
#include <QLocale>

namespace stellwerk::ui {

StartupProgress::StartupProgress(QWidget* parent) : QProgressBar(parent) {
    setObjectName(QStringLiteral("startupProgress"));
    setTextVisible(true);
    setMinimumWidth(fontMetrics().averageCharWidth() * 44);
    setMaximumHeight(fontMetrics().height() + 4);
    refresh();
}

void StartupProgress::setConnection(const connection::StationConnection* station) {
    if (m_connection)
        disconnect(m_connection, nullptr, this, nullptr);
    m_connection = station;
    if (m_connection) {
        connect(m_connection, &connection::StationConnection::stateChanged, this, &StartupProgress::refresh);
        connect(m_connection, &connection::StationConnection::progressChanged, this,
                &StartupProgress::refresh);
    }
    refresh();
}

QString StartupProgress::describe(const connection::LoadingProgress& progress) {
    if (progress.step != connection::LoadingStep::DownloadingFiles || progress.file.isEmpty())
        return tr("Step %1 of %2").arg(progress.stepNumber).arg(progress.stepCount);
    const QLocale locale;
    const QString received = locale.formattedDataSize(progress.received, 1, QLocale::DataSizeSIFormat);
    const QString file = tr("file %1 of %2").arg(progress.fileNumber).arg(progress.fileCount);
    if (progress.announced <= 0)
        return tr("%1: %2 (%3)").arg(progress.file, received, file);
    const QString total = locale.formattedDataSize(progress.announced, 1, QLocale::DataSizeSIFormat);
    return tr("%1: %2 of %3 (%4)").arg(progress.file, received, total, file);
}

void StartupProgress::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QProgressBar::changeEvent(event);
}

// The bar shows the current file's bytes when its size is known, else the steps done.
void StartupProgress::refresh() {
    const bool loading =
        m_connection && m_connection->state() == connection::StationConnection::State::LoadingConfiguration;
    setVisible(loading);
    if (!loading)
        return;
    const connection::LoadingProgress& progress = m_connection->progress();
    if (const auto percent = progress.percent(); percent && !progress.file.isEmpty()) {
        setRange(0, 100);
        setValue(*percent);
    } else {
        setRange(0, progress.stepCount);
        setValue(std::max(0, progress.stepNumber - 1));
    }
    setFormat(describe(progress));
    setToolTip(ConnectionStatus::statusText(m_connection));
}

} // namespace stellwerk::ui
