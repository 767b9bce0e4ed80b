#include "BusMonitorLog.h"

#include "cs2/FrameText.h"

#include <QTextStream>
#include <optional>

namespace stellwerk::ui {
namespace {

const QByteArray interfaceName = QByteArrayLiteral("can0");

// The "(seconds.micros)" a candump log line starts with, if it has one.
std::optional<QDateTime> lineTime(const QString& line) {
    if (!line.startsWith(QLatin1Char('(')))
        return std::nullopt;
    const qsizetype end = line.indexOf(QLatin1Char(')'));
    if (end < 0)
        return std::nullopt;
    bool ok = false;
    const double seconds = line.mid(1, end - 1).toDouble(&ok);
    if (!ok)
        return std::nullopt;
    return QDateTime::fromMSecsSinceEpoch(qint64(seconds * 1000.0 + 0.5));
}

} // namespace

QString BusMonitorLogWriter::open(const QString& path) {
    close();
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
        return m_file.errorString();
    return {};
}

void BusMonitorLogWriter::close() {
    if (m_file.isOpen())
        m_file.close();
}

bool BusMonitorLogWriter::write(std::span<const cs2::CanFrame> frames, const QDateTime& time) {
    if (!m_file.isOpen())
        return false;
    const qint64 ms = time.toMSecsSinceEpoch();
    const QByteArray prefix = QByteArray("(") + QByteArray::number(ms / 1000) + '.' +
                              QByteArray::number((ms % 1000) * 1000).rightJustified(6, '0') + ") " +
                              interfaceName + ' ';
    QByteArray lines;
    lines.reserve(qsizetype(frames.size()) * 48);
    for (const cs2::CanFrame& frame : frames)
        lines += prefix + QByteArray::fromStdString(cs2::formatCandump(frame)) + '\n';
    return m_file.write(lines) == lines.size();
}

BusMonitorLogSummary
readCandumpLog(const QString& path,
               const std::function<void(const cs2::CanFrame&, const QDateTime&)>& frame) {
    BusMonitorLogSummary summary;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        summary.error = file.errorString();
        return summary;
    }
    QTextStream in(&file);
    QDateTime time = QDateTime::currentDateTime();
    int number = 0;
    QString line;
    while (in.readLineInto(&line)) {
        ++number;
        const QString trimmed = line.trimmed();
        if (trimmed.isEmpty() || trimmed.startsWith(QLatin1Char('#')))
            continue;
        const auto parsed = cs2::parseFrame(trimmed.toStdString());
        if (!parsed) {
            ++summary.skipped;
            if (summary.firstSkippedLine == 0)
                summary.firstSkippedLine = number;
            continue;
        }
        if (const auto stamped = lineTime(trimmed))
            time = *stamped;
        frame(parsed.value().frame, time);
        ++summary.frames;
    }
    return summary;
}

} // namespace stellwerk::ui
