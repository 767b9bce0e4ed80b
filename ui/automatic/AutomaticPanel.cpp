#include "automatic/AutomaticPanel.h"

#include "automatic/ScheduleDialog.h"
#include "automatic/TrainStateText.h"
#include "common/PlaceTrainDialog.h"
#include "model/Railway.h"
#include "operation/Operation.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stellwerk::ui {

using automation::TrainMode;
using automation::TrainState;

AutomaticPanel::AutomaticPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("automaticPanel"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("automaticStatus"));
    m_status->setWordWrap(true);
    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("automaticTrains"));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(StateColumn, QHeaderView::Stretch);
    m_table->setWordWrap(false);
    // Compact rows, and a table that shrinks with a low dock (it scrolls itself) instead of the panel.
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    m_table->setMinimumHeight(m_table->horizontalHeader()->sizeHint().height() +
                              2 * (fontMetrics().height() + 8));
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &AutomaticPanel::updateButtons);
    m_event = new QLabel(this);
    m_event->setObjectName(QStringLiteral("automaticEvent"));
    m_event->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_event->hide(); // until something happened
    m_fault = new QLabel(this);
    m_fault->setObjectName(QStringLiteral("automaticFault"));
    m_fault->setWordWrap(true);
    m_fault->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold;"));
    m_fault->hide();
    createButtons();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    auto* actions = new QHBoxLayout;
    for (QPushButton* button : {m_place, m_start, m_stop, m_handBack, m_schedule, m_remove})
        actions->addWidget(button);
    actions->addStretch();
    actions->addWidget(m_resume);
    actions->addWidget(m_stopAll);
    layout->addLayout(actions);
    layout->addWidget(m_status);
    layout->addWidget(m_fault); // above the table: a low dock cuts the table, never the last fault
    layout->addWidget(m_event);
    layout->addWidget(m_table, 1);
    retranslate();
    refresh();
}

void AutomaticPanel::createButtons() {
    const auto button = [this](const char* name) {
        auto* made = new QPushButton(this);
        made->setObjectName(QString::fromLatin1(name));
        return made;
    };
    m_place = button("placeTrainButton");
    m_start = button("startTrainButton");
    m_stop = button("stopTrainButton");
    m_handBack = button("handBackButton");
    m_schedule = button("scheduleButton");
    m_remove = button("removeTrainButton");
    m_resume = button("resumeButton");
    m_stopAll = button("stopAllAtNextStopButton");
    connect(m_place, &QPushButton::clicked, this, &AutomaticPanel::openPlaceDialog);
    connect(m_schedule, &QPushButton::clicked, this, &AutomaticPanel::openScheduleDialog);
    const auto onSelected = [this](auto action) {
        return [this, action] {
            if (const auto locId = selectedTrain(); locId && m_operation)
                action(*locId);
        };
    };
    connect(m_start, &QPushButton::clicked, this,
            onSelected([this](std::uint32_t locId) { act(m_operation->start(locId)); }));
    connect(m_handBack, &QPushButton::clicked, this,
            onSelected([this](std::uint32_t locId) { act(m_operation->start(locId)); }));
    connect(m_stop, &QPushButton::clicked, this,
            onSelected([this](std::uint32_t locId) { m_operation->stop(locId); }));
    connect(m_remove, &QPushButton::clicked, this,
            onSelected([this](std::uint32_t locId) { m_operation->remove(locId); }));
    connect(m_resume, &QPushButton::clicked, this, [this] {
        if (m_operation)
            act(m_operation->resume());
    });
    connect(m_stopAll, &QPushButton::clicked, this, [this] {
        if (m_operation)
            m_operation->stopAllAtNextStop();
    });
}

void AutomaticPanel::setOperation(operation::Operation* operation) {
    if (m_operation)
        disconnect(m_operation, nullptr, this, nullptr);
    m_operation = operation;
    if (m_operation) {
        connect(m_operation, &operation::Operation::changed, this, &AutomaticPanel::refresh);
        connect(m_operation, &operation::Operation::happened, this, &AutomaticPanel::eventHappened);
        connect(m_operation, &operation::Operation::bookTrouble, this, [this](const QString& sentence) {
            m_fault->setText(tr("Trains' book: %1").arg(sentence));
            m_fault->show();
        });
        if (!m_operation->bookProblem().empty()) {
            m_fault->setText(tr("Trains' book: %1").arg(QString::fromStdString(m_operation->bookProblem())));
            m_fault->show();
        }
    }
    refresh();
}

void AutomaticPanel::setAutomation(automation::Automation* /*automation*/) {
    refresh(); // the operation holds it; the table is made anew from it
}

void AutomaticPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void AutomaticPanel::retranslate() {
    m_table->setHorizontalHeaderLabels(
        {tr("Train"), tr("Block"), tr("State"), tr("Destination"), tr("Schedule")});
    m_place->setText(tr("&Place…"));
    m_place->setToolTip(tr("Put a locomotive in a block of the track plan, facing one end"));
    m_start->setText(tr("S&tart"));
    m_start->setToolTip(tr("The automation drives the train from where it stands"));
    m_stop->setText(tr("St&op"));
    m_stop->setToolTip(tr("The train stops and becomes manual; its track stays reserved for it"));
    m_handBack->setText(tr("&Hand back"));
    m_handBack->setToolTip(tr("Give a train a throttle took back to the automation, where it stands"));
    m_schedule->setText(tr("Sche&dule…"));
    m_schedule->setToolTip(tr("The blocks the train runs to, how long it stands at each, once or in a loop"));
    m_remove->setText(tr("Re&move"));
    m_remove->setToolTip(tr("Take the train off the automation and out of the book"));
    m_resume->setText(tr("&Resume"));
    m_resume->setToolTip(tr("After STOP, a fault or a restart: the automatic trains go on"));
    m_stopAll->setText(tr("Stop all at next stop"));
    m_stopAll->setToolTip(tr("Every automatic train runs on to its next stop and stays there, manual"));
    refresh();
}

QString AutomaticPanel::trainName(std::uint32_t locId) const {
    if (m_operation && m_operation->railway())
        if (const model::Locomotive* loco = m_operation->railway()->locomotive(locId))
            return loco->displayName();
    return QStringLiteral("0x%1").arg(locId, 4, 16, QLatin1Char('0'));
}

void AutomaticPanel::refresh() {
    const std::optional<std::uint32_t> selected = selectedTrain();
    const QSignalBlocker quiet(m_table);
    m_table->setRowCount(0);
    if (m_operation) {
        for (const operation::BookedTrain& train : m_operation->book().trains()) {
            const int row = m_table->rowCount();
            m_table->insertRow(row);
            fillRow(row, train.locId);
        }
    }
    if (selected)
        selectTrain(*selected);
    else if (m_table->rowCount() > 0)
        m_table->selectRow(0);
    updateButtons();
}

void AutomaticPanel::fillRow(int row, std::uint32_t locId) {
    const operation::BookedTrain* booked = m_operation->book().find(locId);
    const automation::Automation* automation = m_operation->automation();
    const automation::Train* train = automation ? automation->dispatcher().train(locId) : nullptr;
    const auto cell = [&](int column, const QString& text) {
        auto* item = new QTableWidgetItem(text);
        item->setData(Qt::UserRole, QVariant::fromValue(locId));
        item->setToolTip(text);
        m_table->setItem(row, column, item);
        return item;
    };
    cell(TrainColumn, trainName(locId));
    cell(BlockColumn, train ? QString::fromStdString(booked->block) : QStringLiteral("–"));
    QTableWidgetItem* state = cell(StateColumn, TrainStateText::state(*m_operation, locId));
    if (TrainStateText::trouble(*m_operation, locId))
        state->setForeground(QColor(0xb0, 0x00, 0x20));
    const bool heading = train && train->destination;
    cell(DestinationColumn,
         heading ? QString::fromStdString(automation->dispatcher().graph().block(*train->destination).name)
                 : QStringLiteral("–"));
    cell(ScheduleColumn, TrainStateText::schedule(booked->schedule));
}

int AutomaticPanel::rowOf(std::uint32_t locId) const {
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (m_table->item(row, TrainColumn)->data(Qt::UserRole).value<std::uint32_t>() == locId)
            return row;
    return -1;
}

void AutomaticPanel::selectTrain(std::uint32_t locId) {
    if (const int row = rowOf(locId); row >= 0)
        m_table->selectRow(row);
}

std::optional<std::uint32_t> AutomaticPanel::selectedTrain() const {
    const QList<QTableWidgetItem*> items = m_table->selectedItems();
    if (items.isEmpty())
        return std::nullopt;
    return items.front()->data(Qt::UserRole).value<std::uint32_t>();
}

void AutomaticPanel::updateButtons() {
    const automation::Automation* automation = m_operation ? m_operation->automation() : nullptr;
    const std::optional<std::uint32_t> locId = selectedTrain();
    const automation::Train* train = automation && locId ? automation->dispatcher().train(*locId) : nullptr;
    const bool automatic = train && train->mode == TrainMode::Automatic;
    const bool waiting = train && m_operation->waitsForResume(*locId);
    const bool byHand = train && m_operation->takenByHand(*locId);
    m_place->setEnabled(automation != nullptr);
    m_start->setEnabled(train && !byHand && train->state != TrainState::Lost &&
                        (!automatic || train->state == TrainState::Fault));
    m_stop->setEnabled(automatic || waiting);
    m_handBack->setEnabled(byHand && !automatic);
    m_schedule->setEnabled(locId.has_value() && automation != nullptr);
    m_remove->setEnabled(locId.has_value());
    const bool halted = m_operation && m_operation->halted();
    m_resume->setEnabled(halted);
    m_stopAll->setEnabled(
        automation &&
        std::any_of(automation->dispatcher().trains().begin(), automation->dispatcher().trains().end(),
                    [](const auto& entry) { return entry.second.mode == TrainMode::Automatic; }));
    if (!m_operation || !automation)
        m_status->setText(tr("Automatic operation needs a station (or an opened layout) with a track plan."));
    else if (halted)
        m_status->setText(
            tr("Automation is stopped (STOP, a fault or a restart): nothing moves until you press "
               "Resume."));
    else if (m_operation->book().empty())
        m_status->setText(tr("No trains yet: place one with Place…, then start it."));
    else
        m_status->clear();
    m_status->setVisible(!m_status->text().isEmpty()); // a line only when there is something to do
    m_table->setToolTip(
        m_operation && !m_operation->bookPath().empty()
            ? tr("Trains are saved in %1").arg(QString::fromStdString(m_operation->bookPath().string()))
            : QString());
}

void AutomaticPanel::eventHappened(const automation::AutomationEvent& event) {
    using Kind = automation::AutomationEvent::Kind;
    const QString text = QString::fromStdString(event.text);
    // An unknown occupant alone stops nobody (a train it stops gets a fault of its own): a passing event.
    const bool fault = event.kind == Kind::Fault || event.kind == Kind::Lost || event.kind == Kind::Overrun;
    m_event->setText(text);
    m_event->setVisible(!fault); // a fault is said once, on the red line
    if (fault) {
        m_fault->setText(tr("Last fault: %1").arg(text));
        m_fault->show();
    }
}

void AutomaticPanel::act(const std::optional<std::string>& problem) {
    if (problem) {
        m_fault->setText(QString::fromStdString(*problem));
        m_fault->show();
    }
}

void AutomaticPanel::openPlaceDialog() {
    const automation::Automation* automation = m_operation ? m_operation->automation() : nullptr;
    if (!automation || !m_operation->railway())
        return;
    PlaceTrainDialog::Choice start;
    if (const auto locId = selectedTrain()) {
        start.locId = *locId;
        if (const operation::BookedTrain* booked = m_operation->book().find(*locId))
            start = {*locId, booked->blockId, booked->towards, booked->lengthMm, booked->pushPull};
    }
    m_placeDialog =
        new PlaceTrainDialog(*m_operation->railway(), automation->dispatcher().graph(), start, this);
    m_placeDialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_placeDialog, &QDialog::accepted, this, [this, dialog = m_placeDialog] {
        if (!m_operation || !dialog)
            return;
        const PlaceTrainDialog::Choice choice = dialog->choice();
        act(m_operation->place(choice.locId, choice.block, choice.towards, choice.lengthMm, choice.pushPull));
        selectTrain(choice.locId);
    });
    m_placeDialog->open();
}

void AutomaticPanel::openScheduleDialog() {
    const std::optional<std::uint32_t> locId = selectedTrain();
    const operation::BookedTrain* booked = m_operation && locId ? m_operation->book().find(*locId) : nullptr;
    if (!booked || !m_operation->automation())
        return;
    std::vector<std::string> blocks;
    for (const trackgraph::Block& block : m_operation->automation()->dispatcher().graph().blocks())
        blocks.push_back(block.name);
    m_scheduleDialog = new ScheduleDialog(trainName(*locId), std::move(blocks), booked->schedule, this);
    m_scheduleDialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_scheduleDialog, &QDialog::accepted, this, [this, train = *locId, dialog = m_scheduleDialog] {
        if (m_operation && dialog)
            act(m_operation->setSchedule(train, dialog->schedule()));
    });
    m_scheduleDialog->open();
}

} // namespace stellwerk::ui
