#include "monitor/BusMonitorTable.h"

#include "monitor/BusMonitorModel.h"

#include <QEvent>
#include <QFontDatabase>
#include <QHeaderView>
#include <QScrollBar>
#include <algorithm>

namespace stellwerk::ui {

BusMonitorTable::BusMonitorTable(QAbstractItemModel* rows, QWidget* parent) : QTableView(parent) {
    setObjectName(QStringLiteral("busMonitorTable"));
    setModel(rows);
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setWordWrap(false);
    setShowGrid(false);
    verticalHeader()->hide();
    verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
    horizontalHeader()->setHighlightSections(false);
    horizontalHeader()->setStretchLastSection(false);
    horizontalHeader()->setSectionResizeMode(BusMonitorModel::DetailsColumn, QHeaderView::Stretch);
    setBusColumnShown(false);
    fitColumns();
    fitBusColumn({});
    QScrollBar* scroll = verticalScrollBar();
    connect(scroll, &QScrollBar::valueChanged, this,
            [this, scroll](int value) { m_followNewest = value >= scroll->maximum(); });
    connect(scroll, &QScrollBar::rangeChanged, this, &BusMonitorTable::followNewest);
}

void BusMonitorTable::setBusColumnShown(bool shown) {
    setColumnHidden(BusMonitorModel::BusColumn, !shown);
}

void BusMonitorTable::fitBusColumn(const QStringList& names) {
    const QFontMetrics metrics = fontMetrics();
    const int digit = metrics.horizontalAdvance(QLatin1Char('0'));
    int widest = digit * 8;
    for (const QString& name : names)
        widest = std::max(widest, metrics.horizontalAdvance(name));
    horizontalHeader()->resizeSection(BusMonitorModel::BusColumn, std::min(widest, digit * 32) + digit * 2);
}

void BusMonitorTable::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        fitColumns();
    QTableView::changeEvent(event);
}

void BusMonitorTable::fitColumns() {
    const QFontMetrics metrics = fontMetrics();
    const int digit = metrics.horizontalAdvance(QLatin1Char('0'));
    const auto width = [&](const QString& text) { return metrics.horizontalAdvance(text) + digit * 2; };
    QHeaderView* header = horizontalHeader();
    header->resizeSection(BusMonitorModel::TimeColumn, width(QStringLiteral("00:00:00.000")));
    header->resizeSection(
        BusMonitorModel::DirectionColumn,
        std::max({width(BusMonitorModel::directionText(BusMonitorModel::Direction::Received)),
                  width(BusMonitorModel::directionText(BusMonitorModel::Direction::Sent)), digit * 12}));
    header->resizeSection(BusMonitorModel::MessageColumn, digit * 26);
    header->resizeSection(BusMonitorModel::FrameColumn,
                          width(QStringLiteral("00000000 8 00 00 00 00 00 00 00 00")));
}

void BusMonitorTable::followNewest() {
    if (m_followNewest)
        scrollToBottom();
}

} // namespace stellwerk::ui
