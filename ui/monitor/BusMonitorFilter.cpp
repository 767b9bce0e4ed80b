#include "monitor/BusMonitorFilter.h"

#include "busreading/FrameDescription.h"
#include "monitor/BusMonitorModel.h"

#include <QElapsedTimer>
#include <QStringList>
#include <QTimer>
#include <algorithm>
#include <vector>

namespace stellwerk::ui {

BusMonitorFilter::BusMonitorFilter(QObject* parent)
    : QAbstractProxyModel(parent), m_scanTimer(new QTimer(this)) {
    m_scanTimer->setSingleShot(true);
    m_scanTimer->setInterval(0);
    connect(m_scanTimer, &QTimer::timeout, this, &BusMonitorFilter::scanSome);
}

BusMonitorFilter::~BusMonitorFilter() = default;

// Only a BusMonitorModel can be filtered: the row numbers that survive dropping the oldest come from it.
void BusMonitorFilter::setSourceModel(QAbstractItemModel* model) {
    if (m_source)
        disconnect(m_source, nullptr, this, nullptr);
    beginResetModel();
    m_source = qobject_cast<BusMonitorModel*>(model);
    QAbstractProxyModel::setSourceModel(m_source);
    endResetModel();
    if (!m_source)
        return;
    connect(m_source, &QAbstractItemModel::rowsAboutToBeRemoved, this,
            &BusMonitorFilter::sourceAboutToRemove);
    connect(m_source, &QAbstractItemModel::rowsRemoved, this, &BusMonitorFilter::sourceRemoved);
    connect(m_source, &QAbstractItemModel::rowsAboutToBeInserted, this,
            &BusMonitorFilter::sourceAboutToInsert);
    connect(m_source, &QAbstractItemModel::rowsInserted, this, &BusMonitorFilter::sourceInserted);
    connect(m_source, &QAbstractItemModel::modelAboutToBeReset, this, &BusMonitorFilter::sourceAboutToReset);
    connect(m_source, &QAbstractItemModel::modelReset, this, &BusMonitorFilter::sourceReset);
    connect(m_source, &QAbstractItemModel::headerDataChanged, this, &QAbstractItemModel::headerDataChanged);
    restart();
}

void BusMonitorFilter::setCommand(const QString& name) {
    setFilters(name, m_locId, m_text);
}

void BusMonitorFilter::setProtocol(std::optional<busreading::Protocol> protocol) {
    if (protocol == m_protocol)
        return;
    m_protocol = protocol;
    restart();
}

void BusMonitorFilter::setHandheld(std::optional<busreading::HandheldReference> handheld) {
    if (handheld == m_handheld)
        return;
    m_handheld = std::move(handheld);
    restart();
}

void BusMonitorFilter::setLocId(std::optional<std::uint32_t> locId) {
    setFilters(m_command, locId, m_text);
}

void BusMonitorFilter::setText(const QString& text) {
    setFilters(m_command, m_locId, text);
}

void BusMonitorFilter::setFilters(const QString& command, std::optional<std::uint32_t> locId,
                                  const QString& text) {
    if (take(command, locId, text))
        restart();
}

bool BusMonitorFilter::take(const QString& command, std::optional<std::uint32_t> locId, const QString& text) {
    if (command == m_command && locId == m_locId && text == m_text)
        return false;
    m_command = command;
    m_commandName = command.toStdString();
    m_locId = locId;
    m_text = text;
    m_lowerText = text.toLower().toStdString();
    return true;
}

bool BusMonitorFilter::isScanning() const {
    return !m_passThrough && m_source && m_scanned < sourceEnd();
}

int BusMonitorFilter::scanPercent() const {
    const std::uint64_t end = m_source ? sourceEnd() : 0;
    if (m_passThrough || end <= m_scanStart || m_scanned >= end)
        return 100;
    return int((m_scanned - std::min(m_scanned, m_scanStart)) * 100 / (end - m_scanStart));
}

std::optional<std::uint32_t> BusMonitorFilter::parseLocId(const QString& text) {
    return busreading::parseLocoReference(text.toStdString());
}

// Cheap tests first: each reads the row's description (decoded once and cached), the text all its text.
bool BusMonitorFilter::accepts(int sourceRow) const {
    if (m_protocol && m_source->protocolAt(sourceRow) != *m_protocol)
        return false;
    if (m_handheld) {
        const auto handheld = m_source->handheldAt(sourceRow);
        if (!handheld || !m_handheld->matches(*handheld))
            return false;
    }
    if (!m_commandName.empty() && m_source->commandAt(sourceRow) != m_commandName)
        return false;
    if (m_locId && m_source->locIdAt(sourceRow) != m_locId)
        return false;
    return m_lowerText.empty() || m_source->containsText(sourceRow, m_lowerText);
}

// Forgets what passed and tests every row again, the first slice at once.
void BusMonitorFilter::restart() {
    m_scanTimer->stop();
    beginResetModel();
    m_rows.clear();
    m_passThrough = !isFiltering();
    m_scanStart = m_source ? m_source->firstSequence() : 0;
    m_scanned = m_scanStart;
    endResetModel();
    if (!m_passThrough && m_source)
        scanSome();
}

std::uint64_t BusMonitorFilter::sourceEnd() const {
    return m_source->firstSequence() + std::uint64_t(m_source->rowCount());
}

// Tests the next slice of rows, adds those that pass as one insertion, and comes back for more.
void BusMonitorFilter::scanSome() {
    const std::uint64_t first = m_source->firstSequence();
    m_scanned = std::max(m_scanned, first);
    const std::uint64_t end = sourceEnd();
    std::vector<std::uint64_t> passed;
    QElapsedTimer slice;
    slice.start();
    while (m_scanned < end && (m_scanned % 64 != 0 || slice.elapsed() < SliceMs)) {
        if (accepts(int(m_scanned - first)))
            passed.push_back(m_scanned);
        ++m_scanned;
    }
    if (!passed.empty()) {
        const int at = int(m_rows.size());
        beginInsertRows({}, at, at + int(passed.size()) - 1);
        m_rows.insert(m_rows.end(), passed.begin(), passed.end());
        endInsertRows();
    }
    if (m_scanned < sourceEnd())
        m_scanTimer->start();
    emit scanProgress(scanPercent());
}

void BusMonitorFilter::sourceAboutToRemove(const QModelIndex& parent, int first, int last) {
    if (parent.isValid())
        return;
    Q_ASSERT(first == 0); // the model drops only its oldest rows
    if (m_passThrough) {
        m_removing = std::size_t(last - first + 1);
        return beginRemoveRows({}, first, last);
    }
    const std::uint64_t kept = m_source->firstSequence() + std::uint64_t(last) + 1;
    m_removing = std::size_t(std::lower_bound(m_rows.begin(), m_rows.end(), kept) - m_rows.begin());
    if (m_removing > 0)
        beginRemoveRows({}, 0, int(m_removing) - 1);
}

void BusMonitorFilter::sourceRemoved() {
    if (m_removing == 0)
        return;
    if (!m_passThrough)
        m_rows.erase(m_rows.begin(), m_rows.begin() + std::ptrdiff_t(m_removing));
    m_removing = 0;
    endRemoveRows();
}

void BusMonitorFilter::sourceAboutToInsert(const QModelIndex& parent, int first, int last) {
    m_inserting = m_passThrough && !parent.isValid();
    if (m_inserting)
        beginInsertRows({}, first, last);
}

// New rows come after every row tested so far; a running scan reaches them, else they are tested now.
void BusMonitorFilter::sourceInserted() {
    if (m_inserting) {
        m_inserting = false;
        return endInsertRows();
    }
    if (!m_passThrough && !m_scanTimer->isActive())
        scanSome();
}

void BusMonitorFilter::sourceAboutToReset() {
    m_scanTimer->stop();
    beginResetModel();
}

void BusMonitorFilter::sourceReset() {
    m_rows.clear();
    m_scanStart = m_scanned = 0;
    endResetModel();
}

QModelIndex BusMonitorFilter::index(int row, int column, const QModelIndex& parent) const {
    if (parent.isValid() || row < 0 || column < 0 || row >= rowCount() || column >= columnCount())
        return {};
    return createIndex(row, column);
}

QModelIndex BusMonitorFilter::parent(const QModelIndex&) const {
    return {};
}

int BusMonitorFilter::rowCount(const QModelIndex& parent) const {
    if (parent.isValid() || !m_source)
        return 0;
    return m_passThrough ? m_source->rowCount() : int(m_rows.size());
}

int BusMonitorFilter::columnCount(const QModelIndex& parent) const {
    return parent.isValid() || !m_source ? 0 : m_source->columnCount();
}

QModelIndex BusMonitorFilter::mapToSource(const QModelIndex& proxyIndex) const {
    if (!proxyIndex.isValid() || !m_source)
        return {};
    if (m_passThrough)
        return m_source->index(proxyIndex.row(), proxyIndex.column());
    const std::uint64_t number = m_rows.at(std::size_t(proxyIndex.row()));
    return m_source->index(int(number - m_source->firstSequence()), proxyIndex.column());
}

QModelIndex BusMonitorFilter::mapFromSource(const QModelIndex& sourceIndex) const {
    if (!sourceIndex.isValid() || !m_source)
        return {};
    if (m_passThrough)
        return index(sourceIndex.row(), sourceIndex.column());
    const std::uint64_t number = m_source->firstSequence() + std::uint64_t(sourceIndex.row());
    const auto found = std::lower_bound(m_rows.begin(), m_rows.end(), number);
    if (found == m_rows.end() || *found != number)
        return {};
    return index(int(found - m_rows.begin()), sourceIndex.column());
}

QVariant BusMonitorFilter::headerData(int section, Qt::Orientation orientation, int role) const {
    if (!m_source)
        return {};
    if (orientation == Qt::Horizontal)
        return m_source->headerData(section, orientation, role);
    return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
}

} // namespace stellwerk::ui
