#include "monitor/BusMonitorLog.h"

#include "can/FrameText.h"

namespace stellwerk::ui {
namespace {

QByteArray interfaceName(int bus) {
    return QByteArrayLiteral("can") + QByteArray::number(bus);
}

// The N of the "canN" interface after the time stamp; 0 when the line names another one or none.
int lineBus(const QByteArray& line) {
    const qsizetype start = line.startsWith('(') ? line.indexOf(") ") + 2 : -1;
    if (start < 2 || line.mid(start, 3) != "can")
        return 0;
    const qsizetype end = line.indexOf(' ', start);
    bool ok = false;
    const int bus = line.mid(start + 3, end < 0 ? -1 : end - start - 3).toInt(&ok);
    return ok && bus >= 0 && bus < 256 ? bus : 0;
}

// The "(seconds.micros)" a candump log line starts with, as microseconds, if it has one.
std::optional<qint64> lineTimeUs(const QByteArray& line) {
    if (!line.startsWith('('))
        return std::nullopt;
    const qsizetype end = line.indexOf(')');
    const qsizetype dot = line.indexOf('.');
    if (end < 0)
        return std::nullopt;
    bool ok = false;
    if (dot < 0 || dot > end) {
        const qint64 seconds = line.mid(1, end - 1).toLongLong(&ok);
        return ok ? std::optional<qint64>(seconds * 1000000) : std::nullopt;
    }
    const qint64 seconds = line.mid(1, dot - 1).toLongLong(&ok);
    if (!ok)
        return std::nullopt;
    const QByteArray fraction = line.mid(dot + 1, end - dot - 1).leftJustified(6, '0').left(6);
    const qint64 micros = fraction.toLongLong(&ok);
    return ok ? std::optional<qint64>(seconds * 1000000 + micros) : std::nullopt;
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

bool BusMonitorLogWriter::write(std::span<const can::CanFrame> frames, const QDateTime& time, bool outgoing,
                                int bus) {
    if (!m_file.isOpen())
        return false;
    const qint64 ms = time.toMSecsSinceEpoch();
    const QByteArray prefix = QByteArray("(") + QByteArray::number(ms / 1000) + '.' +
                              QByteArray::number((ms % 1000) * 1000).rightJustified(6, '0') + ") " +
                              interfaceName(bus) + ' ';
    const QByteArray mark = outgoing ? QByteArrayLiteral(" T\n") : QByteArrayLiteral(" R\n");
    QByteArray lines;
    lines.reserve(qsizetype(frames.size()) * 48);
    for (const can::CanFrame& frame : frames)
        lines += prefix + QByteArray::fromStdString(can::formatCandump(frame)) + mark;
    // Handed to the system with each batch: a crash of Stellwerk keeps every frame recorded so far.
    return m_file.write(lines) == lines.size() && m_file.flush();
}

QString BusMonitorLogReader::open(const QString& path) {
    m_file.close();
    m_number = 0;
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::ReadOnly))
        return m_file.errorString();
    return {};
}

std::optional<BusMonitorLogLine> BusMonitorLogReader::next() {
    while (m_file.isOpen() && !m_file.atEnd()) {
        const QByteArray line = m_file.readLine().trimmed();
        ++m_number;
        if (line.isEmpty() || line.startsWith('#'))
            continue;
        BusMonitorLogLine result;
        result.number = m_number;
        const auto parsed = can::parseFrame(std::string_view(line.constData(), std::size_t(line.size())));
        if (!parsed) {
            result.problem = QString::fromStdString(parsed.error());
            return result;
        }
        result.frame = parsed.value().frame;
        result.timeUs = lineTimeUs(line);
        result.sent = line.endsWith(" T");
        result.bus = lineBus(line);
        return result;
    }
    return std::nullopt;
}

} // namespace stellwerk::ui
