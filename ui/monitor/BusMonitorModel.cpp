#include "monitor/BusMonitorModel.h"

#include <QColor>
#include <QGuiApplication>
#include <QPalette>
#include <QTimer>
#include <algorithm>
#include <cctype>
#include <string_view>

namespace stellwerk::ui {
namespace {

// The group of a command, from the first word of its name in the core's vocabulary ("loco.speed").
BusMonitorModel::Group groupOf(std::string_view name) {
    using Group = BusMonitorModel::Group;
    const std::string_view word = name.substr(0, name.find('.'));
    if (word == "system" || word == "ping")
        return Group::System;
    if (word == "loco" || word == "mfx" || word == "config")
        return Group::Loco;
    if (word == "accessory" || word == "automation")
        return Group::Accessory;
    if (word == "feedback")
        return Group::Feedback;
    if (word == "configdata" || word == "statusdata" || word == "connect6021")
        return Group::Stream;
    if (word == "mcan")
        return Group::Handheld;
    return Group::Other;
}

// A light tint of the group's hue over the palette's base colour: the text colour of the palette
// stays readable on it in light and dark themes alike.
QColor tint(BusMonitorModel::Group group) {
    static constexpr int hues[] = {50, 210, 280, 120, 180, 330, -1}; // system yellow, loco blue, ...
    const int hue = hues[int(group)];
    const QColor base = QGuiApplication::palette().color(QPalette::Base);
    if (hue < 0)
        return base;
    const QColor colour = QColor::fromHsv(hue, 200, 230);
    constexpr double share = 0.16;
    return QColor::fromRgbF(float(base.redF() * (1 - share) + colour.redF() * share),
                            float(base.greenF() * (1 - share) + colour.greenF() * share),
                            float(base.blueF() * (1 - share) + colour.blueF() * share));
}

bool darkPalette() {
    return QGuiApplication::palette().color(QPalette::Base).lightness() < 128;
}

// Sent rows in orange, received ones in blue, dark on light themes and light on dark ones.
QColor directionColour(BusMonitorModel::Direction direction) {
    const bool sent = direction == BusMonitorModel::Direction::Sent;
    if (darkPalette())
        return sent ? QColor::fromHsv(28, 150, 255) : QColor::fromHsv(205, 110, 255);
    return sent ? QColor::fromHsv(24, 255, 180) : QColor::fromHsv(210, 255, 160);
}

template <class Record>
can::CanFrame frameOf(const Record& r) {
    can::CanFrame frame;
    frame.id = r.id;
    frame.dlc = r.dlc;
    frame.data = r.data;
    frame.extended = r.extended;
    return frame;
}

QString latin1(std::string_view text) {
    return QString::fromLatin1(text.data(), qsizetype(text.size()));
}

} // namespace

BusMonitorModel::BusMonitorModel(QObject* parent)
    : QAbstractTableModel(parent), m_flushTimer(new QTimer(this)) {
    m_flushTimer->setSingleShot(true);
    m_flushTimer->setInterval(FlushIntervalMs);
    connect(m_flushTimer, &QTimer::timeout, this, &BusMonitorModel::flush);
}

BusMonitorModel::Record BusMonitorModel::record(const can::CanFrame& frame, Direction direction,
                                                qint64 timeMs, int bus) {
    return Record{timeMs, frame.id, frame.dlc, direction, frame.extended, std::uint8_t(bus), frame.data};
}

void BusMonitorModel::setBuses(std::vector<MonitoredBus> buses) {
    m_buses = std::move(buses);
    m_descriptions.clear(); // a bus may expect other protocols now
    noteBus(int(m_buses.size()) - 1);
    if (!m_rows.empty())
        emit dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1));
}

QString BusMonitorModel::busName(int bus) const {
    if (bus >= 0 && std::size_t(bus) < m_buses.size() && !m_buses[std::size_t(bus)].name.isEmpty())
        return m_buses[std::size_t(bus)].name;
    return QStringLiteral("can%1").arg(bus);
}

const busreading::BusProfile& BusMonitorModel::profileOf(int bus) const {
    static const busreading::BusProfile station = busreading::BusProfile::centralStation();
    static const busreading::BusProfile none{};
    if (std::size_t(bus) < m_buses.size())
        return m_buses[std::size_t(bus)].profile;
    return bus == 0 ? station : none;
}

busreading::BusContext& BusMonitorModel::contextOf(int bus) {
    if (std::size_t(bus) >= m_contexts.size())
        m_contexts.resize(std::size_t(bus) + 1);
    return m_contexts[std::size_t(bus)];
}

void BusMonitorModel::noteBus(int bus) {
    if (bus + 1 <= m_busCount)
        return;
    const bool mattered = m_busCount > 1;
    m_busCount = bus + 1;
    if (!mattered && m_busCount > 1)
        emit busCountChanged(m_busCount);
}

void BusMonitorModel::addFrames(std::span<const can::CanFrame> frames, Direction direction) {
    addFrames(frames, direction, QDateTime::currentDateTime());
}

void BusMonitorModel::addFrames(std::span<const can::CanFrame> frames, Direction direction,
                                const QDateTime& time, int bus) {
    if (frames.empty())
        return;
    bus = std::clamp(bus, 0, 255);
    noteBus(bus);
    const qint64 timeMs = time.toMSecsSinceEpoch();
    busreading::BusContext& context = contextOf(bus);
    for (const can::CanFrame& frame : frames) {
        m_queued.push_back(record(frame, direction, timeMs, bus));
        context.observe(frame); // in arrival order, also while paused and for frames the queue drops
    }
    // Never hold more than the table could show: the oldest queued frames would be dropped anyway.
    const auto limit = std::size_t(m_historyLimit);
    if (m_queued.size() > limit)
        m_queued.erase(m_queued.begin(), m_queued.begin() + std::ptrdiff_t(m_queued.size() - limit));
    m_total += frames.size();
    if (m_paused)
        m_heldBack += frames.size();
    if (!m_flushTimer->isActive())
        m_flushTimer->start();
}

void BusMonitorModel::flush() {
    m_flushTimer->stop();
    if (m_paused) {
        emit countsChanged();
        return;
    }
    if (m_queued.empty())
        return;
    const auto limit = std::size_t(m_historyLimit);
    const std::size_t incoming = m_queued.size(); // at most `limit`, see addFrames()
    if (m_rows.size() + incoming > limit)
        dropOldest(m_rows.size() + incoming - limit);
    const int first = int(m_rows.size());
    beginInsertRows({}, first, first + int(incoming) - 1);
    m_rows.insert(m_rows.end(), m_queued.begin(), m_queued.end());
    endInsertRows();
    m_queued.clear();
    emit countsChanged();
}

void BusMonitorModel::dropOldest(std::size_t count) {
    count = std::min(count, m_rows.size());
    if (count == 0)
        return;
    beginRemoveRows({}, 0, int(count) - 1);
    m_rows.erase(m_rows.begin(), m_rows.begin() + std::ptrdiff_t(count));
    m_dropped += count;
    endRemoveRows();
}

void BusMonitorModel::setHistoryLimit(int rows) {
    m_historyLimit = std::max(1, rows);
    const auto limit = std::size_t(m_historyLimit);
    if (m_rows.size() > limit)
        dropOldest(m_rows.size() - limit);
    if (m_queued.size() > limit)
        m_queued.erase(m_queued.begin(), m_queued.begin() + std::ptrdiff_t(m_queued.size() - limit));
}

void BusMonitorModel::setPaused(bool paused) {
    if (paused == m_paused)
        return;
    m_paused = paused;
    m_heldBack = 0;
    if (!m_paused)
        flush();
    emit countsChanged();
}

void BusMonitorModel::clear() {
    beginResetModel();
    m_rows.clear();
    m_rows.shrink_to_fit();
    m_queued.clear();
    m_dropped = 0;
    m_descriptions.clear();
    endResetModel();
    m_total = 0;
    m_heldBack = 0;
    const bool mattered = m_busCount > 1;
    m_busCount = std::max(1, int(m_buses.size()));
    if (mattered && m_busCount == 1)
        emit busCountChanged(m_busCount);
    emit countsChanged();
}

void BusMonitorModel::forgetBusContexts() {
    m_contexts.clear();
    m_descriptions.clear();
}

can::CanFrame BusMonitorModel::frameAt(int row) const {
    return frameOf(m_rows.at(std::size_t(row)));
}

const busreading::FrameDescription& BusMonitorModel::describe(int row) const {
    const Record& r = m_rows.at(std::size_t(row));
    const busreading::BusContext* context =
        std::size_t(r.bus) < m_contexts.size() ? &m_contexts[r.bus] : nullptr;
    return m_descriptions.of(m_dropped + std::uint64_t(row), frameOf(r), profileOf(r.bus), context);
}

QString BusMonitorModel::directionText(Direction direction) {
    return direction == Direction::Received ? tr("← received") : tr("→ sent");
}

int BusMonitorModel::busAt(int row) const {
    return m_rows.at(std::size_t(row)).bus;
}

busreading::Protocol BusMonitorModel::protocolAt(int row) const {
    return describe(row).protocol();
}

QDateTime BusMonitorModel::timeAt(int row) const {
    return QDateTime::fromMSecsSinceEpoch(m_rows.at(std::size_t(row)).timeMs);
}

BusMonitorModel::Direction BusMonitorModel::directionAt(int row) const {
    return m_rows.at(std::size_t(row)).direction;
}

std::string BusMonitorModel::commandAt(int row) const {
    return std::string(describe(row).name());
}

bool BusMonitorModel::containsText(int row, std::string_view lowerNeedle) const {
    const busreading::FrameDescription& description = describe(row);
    const auto contains = [lowerNeedle](std::string_view text) {
        const auto equal = [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; };
        return std::search(text.begin(), text.end(), lowerNeedle.begin(), lowerNeedle.end(), equal) !=
               text.end();
    };
    return contains(description.name()) || contains(description.detailText()) ||
           contains(description.frameText());
}

std::optional<std::uint32_t> BusMonitorModel::locIdAt(int row) const {
    const auto locId = describe(row).number("locId");
    return locId ? std::optional<std::uint32_t>(std::uint32_t(*locId)) : std::nullopt;
}

// The handheld's name as its bus knows it now, so that a row described before the name came matches too.
std::optional<busreading::Handheld> BusMonitorModel::handheldAt(int row) const {
    auto handheld = describe(row).handheld();
    const std::size_t bus = m_rows.at(std::size_t(row)).bus;
    if (handheld && bus < m_contexts.size())
        handheld->name = m_contexts[bus].handheldName(handheld->node);
    return handheld;
}

int BusMonitorModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int BusMonitorModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant BusMonitorModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= int(m_rows.size()))
        return {};
    const Record& r = m_rows[std::size_t(index.row())];
    switch (role) {
    case Qt::DisplayRole:
        return display(describe(index.row()), r, index.column());
    case Qt::ToolTipRole:
        return index.column() == DetailsColumn ? display(describe(index.row()), r, index.column())
                                               : QVariant();
    case Qt::ForegroundRole:
        return index.column() == DirectionColumn ? directionColour(r.direction) : QVariant();
    case Qt::BackgroundRole:
        return tint(groupOf(describe(index.row()).name()));
    case GroupRole:
        return int(groupOf(describe(index.row()).name()));
    case CommandRole:
        return latin1(describe(index.row()).name());
    case ProtocolRole:
        return latin1(busreading::protocolName(describe(index.row()).protocol()));
    case LocIdRole: {
        const auto locId = locIdAt(index.row());
        return locId ? QVariant::fromValue(uint(*locId)) : QVariant();
    }
    case SearchTextRole: {
        const busreading::FrameDescription& description = describe(index.row());
        return QString::fromStdString(std::string(description.name()) + ' ' + description.detailText() + ' ' +
                                      description.frameText());
    }
    default:
        return {};
    }
}

QVariant BusMonitorModel::display(const busreading::FrameDescription& description, const Record& r,
                                  int column) const {
    switch (column) {
    case TimeColumn:
        return QDateTime::fromMSecsSinceEpoch(r.timeMs).toString(QStringLiteral("HH:mm:ss.zzz"));
    case BusColumn:
        return busName(r.bus);
    case DirectionColumn:
        return directionText(r.direction);
    case MessageColumn:
        return QString::fromUtf8(description.name().data(), qsizetype(description.name().size()));
    case DetailsColumn:
        return QString::fromStdString(description.detailText());
    case FrameColumn:
        return QString::fromStdString(description.frameText());
    default:
        return {};
    }
}

QVariant BusMonitorModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case TimeColumn:
        return tr("Time");
    case BusColumn:
        return tr("Bus");
    case DirectionColumn:
        return tr("Direction");
    case MessageColumn:
        return tr("Message");
    case DetailsColumn:
        return tr("Details");
    case FrameColumn:
        return tr("Frame");
    default:
        return {};
    }
}

} // namespace stellwerk::ui
