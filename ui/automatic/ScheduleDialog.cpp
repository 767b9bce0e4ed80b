#include "automatic/ScheduleDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

namespace stellwerk::ui {

namespace {

enum Column { BlockColumn, DwellColumn };

} // namespace

ScheduleDialog::ScheduleDialog(const QString& train, std::vector<std::string> blocks,
                               const automation::Schedule& schedule, QWidget* parent)
    : QDialog(parent), m_blocks(std::move(blocks)), m_original(schedule) {
    m_question = [](QWidget* dialog) {
        return QMessageBox::question(dialog, tr("Schedule changed"), tr("Keep the changes to the schedule?"),
                                     QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                     QMessageBox::Save);
    };
    setObjectName(QStringLiteral("scheduleDialog"));
    setWindowTitle(tr("Schedule of %1").arg(train));
    m_stops = new QTableWidget(0, 2, this);
    m_stops->setHorizontalHeaderLabels({tr("Stop (block)"), tr("Dwell")});
    m_stops->horizontalHeader()->setSectionResizeMode(BlockColumn, QHeaderView::Stretch);
    m_stops->horizontalHeader()->setSectionResizeMode(DwellColumn, QHeaderView::ResizeToContents);
    m_stops->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_stops->setSelectionMode(QAbstractItemView::SingleSelection);
    for (const automation::ScheduleStop& stop : schedule.stops)
        insertRow(m_stops->rowCount(), stop.block, double(stop.dwellMs) / 1000.0);
    m_add = new QPushButton(tr("&Add stop"), this);
    m_remove = new QPushButton(tr("&Remove stop"), this);
    m_up = new QPushButton(tr("Move &up"), this);
    m_down = new QPushButton(tr("Move &down"), this);
    connect(m_add, &QPushButton::clicked, this, &ScheduleDialog::addStop);
    connect(m_remove, &QPushButton::clicked, this, &ScheduleDialog::removeStop);
    connect(m_up, &QPushButton::clicked, this, [this] { moveStop(-1); });
    connect(m_down, &QPushButton::clicked, this, [this] { moveStop(1); });
    connect(m_stops, &QTableWidget::itemSelectionChanged, this, &ScheduleDialog::updateButtons);
    m_loop = new QCheckBox(tr("Run in a &loop (after the last stop, the first again)"), this);
    m_loop->setChecked(schedule.loop);
    connect(m_loop, &QCheckBox::toggled, this, [this] { m_modified = true; });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ScheduleDialog::reject);
    auto* row = new QHBoxLayout;
    for (QPushButton* button : {m_add, m_remove, m_up, m_down})
        row->addWidget(button);
    row->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_stops, 1);
    layout->addLayout(row);
    layout->addWidget(m_loop);
    layout->addWidget(buttons);
    resize(520, 380);
    updateButtons();
}

void ScheduleDialog::insertRow(int row, const std::string& block, double dwellSeconds) {
    m_stops->insertRow(row);
    auto* blocks = new QComboBox(m_stops);
    for (const std::string& name : m_blocks)
        blocks->addItem(QString::fromStdString(name));
    if (blocks->findText(QString::fromStdString(block)) < 0)
        blocks->addItem(QString::fromStdString(block)); // a block this plan no longer has: kept as it was
    blocks->setCurrentText(QString::fromStdString(block));
    connect(blocks, &QComboBox::currentIndexChanged, this, &ScheduleDialog::changed);
    m_stops->setCellWidget(row, BlockColumn, blocks);
    auto* dwell = new QDoubleSpinBox(m_stops);
    dwell->setRange(0, 3600);
    dwell->setDecimals(1);
    dwell->setSuffix(tr(" s"));
    dwell->setValue(dwellSeconds);
    connect(dwell, &QDoubleSpinBox::valueChanged, this, &ScheduleDialog::changed);
    m_stops->setCellWidget(row, DwellColumn, dwell);
}

void ScheduleDialog::setStop(int row, const std::string& block, double dwellSeconds) {
    static_cast<QComboBox*>(m_stops->cellWidget(row, BlockColumn))
        ->setCurrentText(QString::fromStdString(block));
    static_cast<QDoubleSpinBox*>(m_stops->cellWidget(row, DwellColumn))->setValue(dwellSeconds);
}

void ScheduleDialog::addStop() {
    const int selected = m_stops->currentRow();
    const int row = selected >= 0 ? selected + 1 : m_stops->rowCount();
    insertRow(row, m_blocks.empty() ? std::string() : m_blocks.front(), 5.0);
    m_stops->selectRow(row);
    changed();
}

void ScheduleDialog::removeStop() {
    const int row = m_stops->currentRow();
    if (row < 0)
        return;
    m_stops->removeRow(row);
    changed();
}

// The rows are made anew in their new order: their editors cannot be moved.
void ScheduleDialog::moveStop(int by) {
    const int row = m_stops->currentRow();
    const int to = row + by;
    if (row < 0 || to < 0 || to >= m_stops->rowCount())
        return;
    automation::Schedule edited = schedule();
    std::swap(edited.stops[std::size_t(row)], edited.stops[std::size_t(to)]);
    m_stops->setRowCount(0);
    for (const automation::ScheduleStop& stop : edited.stops)
        insertRow(m_stops->rowCount(), stop.block, double(stop.dwellMs) / 1000.0);
    m_stops->selectRow(to);
    changed();
}

void ScheduleDialog::changed() {
    m_modified = true;
    m_stopsChanged = true;
    updateButtons();
}

void ScheduleDialog::updateButtons() {
    const int row = m_stops->currentRow();
    m_remove->setEnabled(row >= 0);
    m_up->setEnabled(row > 0);
    m_down->setEnabled(row >= 0 && row + 1 < m_stops->rowCount());
}

automation::Schedule ScheduleDialog::schedule() const {
    automation::Schedule edited;
    edited.loop = m_loop->isChecked();
    edited.pushPull = m_original.pushPull;
    for (int row = 0; row < m_stops->rowCount(); ++row) {
        const auto* block = static_cast<const QComboBox*>(m_stops->cellWidget(row, BlockColumn));
        const auto* dwell = static_cast<const QDoubleSpinBox*>(m_stops->cellWidget(row, DwellColumn));
        edited.stops.push_back(
            {block->currentText().toStdString(), std::int64_t(std::lround(dwell->value() * 1000)), 0});
    }
    edited.next = m_stopsChanged || m_original.next > edited.stops.size() ? 0 : m_original.next;
    return edited;
}

// Escape and Cancel: changes not taken are asked about (Save takes them, Cancel stays in the dialog).
void ScheduleDialog::reject() {
    if (!m_modified) {
        QDialog::reject();
        return;
    }
    switch (m_question(this)) {
    case QMessageBox::Save:
        accept();
        return;
    case QMessageBox::Discard:
        QDialog::reject();
        return;
    default:
        return;
    }
}

} // namespace stellwerk::ui
