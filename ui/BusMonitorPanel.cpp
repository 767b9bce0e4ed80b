#include "BusMonitorPanel.h"

#include "BusMonitorLog.h"
#include "BusMonitorModel.h"
#include "BusMonitorSettings.h"
#include "connection/StationConnection.h"

#include <QEvent>
#include <QFileDialog>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollBar>
#include <QSortFilterProxyModel>
#include <QSpinBox>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <limits>

namespace stellwerk::ui {

// Keeps rows whose text contains the filter; decodes a row once per test, and not at all when the
// filter is empty.
class BusMonitorFilter final : public QSortFilterProxyModel {
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

    void setNeedle(const QString& needle) {
        if (needle == m_needle)
            return;
        m_needle = needle;
        invalidateFilter();
    }
    bool isFiltering() const { return !m_needle.isEmpty(); }

protected:
    bool filterAcceptsRow(int row, const QModelIndex& parent) const override {
        if (m_needle.isEmpty())
            return true;
        const QModelIndex index = sourceModel()->index(row, 0, parent);
        return index.data(BusMonitorModel::SearchTextRole).toString().contains(m_needle, Qt::CaseInsensitive);
    }

private:
    QString m_needle;
};

namespace {

constexpr int FilterDelayMs = 200;

// tr()'s %n takes an int; counters beyond that are shown as the largest int.
int plural(std::uint64_t count) {
    return int(std::min<std::uint64_t>(count, std::uint64_t(std::numeric_limits<int>::max())));
}

} // namespace

BusMonitorPanel::BusMonitorPanel(QWidget* parent)
    : QWidget(parent), m_model(new BusMonitorModel(this)), m_filter(new BusMonitorFilter(this)) {
    setObjectName(QStringLiteral("busMonitorPanel"));
    m_filter->setSourceModel(m_model);
    m_filter->setDynamicSortFilter(false);

    m_filterEdit = new QLineEdit(this);
    m_filterEdit->setObjectName(QStringLiteral("busMonitorFilter"));
    m_filterEdit->setClearButtonEnabled(true);
    m_filterTimer = new QTimer(this);
    m_filterTimer->setSingleShot(true);
    m_filterTimer->setInterval(FilterDelayMs);
    connect(m_filterEdit, &QLineEdit::textChanged, m_filterTimer, qOverload<>(&QTimer::start));
    connect(m_filterTimer, &QTimer::timeout, this, &BusMonitorPanel::applyFilter);

    m_pauseButton = new QPushButton(this);
    m_pauseButton->setObjectName(QStringLiteral("busMonitorPause"));
    m_pauseButton->setCheckable(true);
    connect(m_pauseButton, &QPushButton::toggled, this, [this](bool paused) {
        m_model->setPaused(paused);
        retranslate();
    });
    m_clearButton = new QPushButton(this);
    m_clearButton->setObjectName(QStringLiteral("busMonitorClear"));
    connect(m_clearButton, &QPushButton::clicked, m_model, &BusMonitorModel::clear);
    m_recordButton = new QPushButton(this);
    m_recordButton->setObjectName(QStringLiteral("busMonitorRecord"));
    m_recordButton->setCheckable(true);
    connect(m_recordButton, &QPushButton::clicked, this, &BusMonitorPanel::chooseRecording);
    m_openButton = new QPushButton(this);
    m_openButton->setObjectName(QStringLiteral("busMonitorOpenLog"));
    connect(m_openButton, &QPushButton::clicked, this, &BusMonitorPanel::chooseLog);

    m_historyLabel = new QLabel(this);
    m_history = new QSpinBox(this);
    m_history->setObjectName(QStringLiteral("busMonitorHistory"));
    m_history->setRange(BusMonitorSettings::MinimumHistory, BusMonitorSettings::MaximumHistory);
    m_history->setSingleStep(10000);
    m_history->setGroupSeparatorShown(true);
    m_history->setKeyboardTracking(false);
    m_history->setValue(BusMonitorSettings::loadHistory());
    m_model->setHistoryLimit(m_history->value());
    m_historyLabel->setBuddy(m_history);
    connect(m_history, &QSpinBox::valueChanged, this, [this](int frames) {
        m_model->setHistoryLimit(frames);
        BusMonitorSettings::saveHistory(frames);
    });

    m_counter = new QLabel(this);
    m_counter->setObjectName(QStringLiteral("busMonitorCounter"));

    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("busMonitorTable"));
    m_table->setModel(m_filter);
    m_table->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    m_table->setShowGrid(false);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 4);
    QHeaderView* header = m_table->horizontalHeader();
    header->setHighlightSections(false);
    header->setStretchLastSection(false);
    const int digit = m_table->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    header->resizeSection(BusMonitorModel::TimeColumn, digit * 14);
    header->resizeSection(BusMonitorModel::DirectionColumn, digit * 10);
    header->resizeSection(BusMonitorModel::MessageColumn, digit * 26);
    header->setSectionResizeMode(BusMonitorModel::DetailsColumn, QHeaderView::Stretch);
    header->resizeSection(BusMonitorModel::FrameColumn, digit * 38);

    QScrollBar* scroll = m_table->verticalScrollBar();
    connect(scroll, &QScrollBar::valueChanged, this,
            [this, scroll](int value) { m_followNewest = value >= scroll->maximum(); });
    connect(scroll, &QScrollBar::rangeChanged, this, &BusMonitorPanel::followNewest);
    connect(m_model, &BusMonitorModel::countsChanged, this, &BusMonitorPanel::updateCounter);

    auto* bar = new QHBoxLayout;
    bar->addWidget(m_filterEdit, 1);
    bar->addWidget(m_pauseButton);
    bar->addWidget(m_clearButton);
    bar->addSpacing(12);
    bar->addWidget(m_recordButton);
    bar->addWidget(m_openButton);
    bar->addSpacing(12);
    bar->addWidget(m_historyLabel);
    bar->addWidget(m_history);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_counter);
    retranslate();
}

BusMonitorPanel::~BusMonitorPanel() = default;

void BusMonitorPanel::setConnection(connection::StationConnection* station) {
    if (m_connection)
        disconnect(m_connection, nullptr, this, nullptr);
    m_connection = station;
    if (station)
        connect(station, &connection::StationConnection::framesSeen, this, &BusMonitorPanel::receive);
}

void BusMonitorPanel::receive(const std::vector<cs2::CanFrame>& frames, bool outgoing) {
    const QDateTime now = QDateTime::currentDateTime();
    m_model->addFrames(
        frames, outgoing ? BusMonitorModel::Direction::Sent : BusMonitorModel::Direction::Received, now);
    if (m_recorder && !m_recorder->write(frames, now)) {
        const QString file = m_recorder->fileName();
        stopRecording();
        QMessageBox::warning(this, tr("Recording stopped"),
                             tr("The frames could not be written to %1; recording stopped.").arg(file));
    }
}

QString BusMonitorPanel::startRecording(const QString& path) {
    auto recorder = std::make_unique<BusMonitorLogWriter>();
    const QString error = recorder->open(path);
    if (error.isEmpty())
        m_recorder = std::move(recorder);
    m_recordButton->setChecked(isRecording());
    retranslate();
    return error;
}

void BusMonitorPanel::stopRecording() {
    m_recorder.reset();
    m_recordButton->setChecked(false);
    retranslate();
}

bool BusMonitorPanel::isRecording() const {
    return m_recorder != nullptr;
}

void BusMonitorPanel::chooseRecording(bool start) {
    if (!start)
        return stopRecording();
    const QString path = QFileDialog::getSaveFileName(this, tr("Record frames to"), QString(),
                                                      tr("candump logs (*.log);;All files (*)"));
    if (path.isEmpty())
        return stopRecording();
    const QString error = startRecording(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Recording not started"),
                             tr("%1 cannot be written: %2").arg(path, error));
}

QString BusMonitorPanel::openLog(const QString& path) {
    m_model->clear();
    const BusMonitorLogSummary summary =
        readCandumpLog(path, [this](const cs2::CanFrame& frame, const QDateTime& time) {
            m_model->addFrames({&frame, 1}, BusMonitorModel::Direction::Received, time);
        });
    m_model->flush();
    if (!summary.error.isEmpty())
        return summary.error;
    if (summary.skipped > 0)
        return tr("%Ln line(s) held no frame, the first one is line %1.", nullptr, int(summary.skipped))
            .arg(summary.firstSkippedLine);
    return {};
}

void BusMonitorPanel::chooseLog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a candump log"), QString(),
                                                      tr("candump logs (*.log);;All files (*)"));
    if (path.isEmpty())
        return;
    const QString problem = openLog(path);
    if (!problem.isEmpty())
        QMessageBox::warning(this, tr("Log file"), QStringLiteral("%1: %2").arg(path, problem));
}

void BusMonitorPanel::setFilterText(const QString& text) {
    m_filterEdit->setText(text);
    applyFilter();
}

void BusMonitorPanel::applyFilter() {
    m_filterTimer->stop();
    m_filter->setNeedle(m_filterEdit->text().trimmed());
    updateCounter();
}

// Keeps the newest row in sight while the user has not scrolled away from the bottom.
void BusMonitorPanel::followNewest() {
    if (m_followNewest)
        m_table->scrollToBottom();
}

void BusMonitorPanel::updateCounter() {
    QString text = tr("%Ln frame(s) received", nullptr, plural(m_model->totalFrames()));
    if (m_filter->isFiltering())
        text += QStringLiteral(" · ") + tr("%Ln row(s) match the filter", nullptr, m_filter->rowCount());
    if (m_model->isPaused())
        text += QStringLiteral(" · ") +
                tr("paused, %Ln frame(s) arrived since", nullptr, plural(m_model->heldBack()));
    m_counter->setText(text);
}

void BusMonitorPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void BusMonitorPanel::retranslate() {
    m_filterEdit->setPlaceholderText(tr("Filter by message, Loc-ID or bytes, e.g. loco.speed or 0xC003"));
    m_pauseButton->setText(m_pauseButton->isChecked() ? tr("&Resume") : tr("&Pause"));
    m_pauseButton->setToolTip(
        tr("Stop adding rows; frames that arrive meanwhile are kept and shown on resume"));
    m_clearButton->setText(tr("C&lear"));
    m_recordButton->setText(isRecording() ? tr("Stop &recording") : tr("&Record…"));
    m_recordButton->setToolTip(isRecording() ? tr("Recording to %1").arg(m_recorder->fileName())
                                             : tr("Write every frame from now on to a candump log file"));
    m_openButton->setText(tr("&Open log…"));
    m_openButton->setToolTip(tr("Show the frames of a candump log file instead of the current ones"));
    m_historyLabel->setText(tr("&Keep:"));
    m_history->setSuffix(tr(" frames"));
    m_history->setToolTip(tr("How many frames the table keeps; older ones are dropped"));
    emit m_model->headerDataChanged(Qt::Horizontal, 0, BusMonitorModel::ColumnCount - 1);
    updateCounter();
}

} // namespace stellwerk::ui
