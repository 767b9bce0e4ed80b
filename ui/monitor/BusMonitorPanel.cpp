#include "monitor/BusMonitorPanel.h"

#include "common/SideBySide.h"
#include "connection/ConnectionBuses.h"
#include "monitor/BusMonitorFilter.h"
#include "monitor/BusMonitorFilterBar.h"
#include "monitor/BusMonitorLog.h"
#include "monitor/BusMonitorModel.h"
#include "monitor/BusMonitorReplay.h"
#include "monitor/BusMonitorSettings.h"
#include "monitor/BusMonitorTable.h"

#include <QComboBox>
#include <QDateTime>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <limits>

namespace stellwerk::ui {
namespace {

// Below this width the filter line and the file line (record, open, keep) stand one above the other: side by
// side they need about 1,080 px in German.
constexpr int BarsSideBySideWidth = 1150;
constexpr qsizetype MaxSkippedShown = 20; // lines without a frame listed in the replay's tooltip
constexpr double Speeds[] = {1.0, 2.0, 10.0, BusMonitorReplay::AsFastAsPossible};

// tr()'s %n takes an int; counters beyond that are shown as the largest int.
int plural(std::uint64_t count) {
    return int(std::min<std::uint64_t>(count, std::uint64_t(std::numeric_limits<int>::max())));
}

QPushButton* button(QWidget* parent, const char* name, bool checkable = false) {
    auto* result = new QPushButton(parent);
    result->setObjectName(QLatin1String(name));
    result->setCheckable(checkable);
    return result;
}

} // namespace

BusMonitorPanel::BusMonitorPanel(QWidget* parent)
    : QWidget(parent), m_model(new BusMonitorModel(this)), m_filter(new BusMonitorFilter(this)),
      m_replay(new BusMonitorReplay(this)) {
    setObjectName(QStringLiteral("busMonitorPanel"));
    m_filter->setSourceModel(m_model);
    connect(m_replay, &BusMonitorReplay::framesReplayed, this, &BusMonitorPanel::replayed);
    connect(m_replay, &BusMonitorReplay::lineSkipped, this, &BusMonitorPanel::lineSkipped);
    connect(m_replay, &BusMonitorReplay::stateChanged, this, &BusMonitorPanel::replayStateChanged);
    connect(m_model, &BusMonitorModel::busCountChanged, this, &BusMonitorPanel::showBusColumn);

    m_counter = new QLabel(this);
    m_counter->setObjectName(QStringLiteral("busMonitorCounter"));
    m_table = new BusMonitorTable(m_filter, this);
    auto* layout = new QVBoxLayout(this);
    auto* bars = new QHBoxLayout;
    bars->addLayout(createFilterBar(), 1);
    bars->addSpacing(12);
    bars->addLayout(createFileBar());
    SideBySide::arrange(this, bars, BarsSideBySideWidth);
    layout->addLayout(bars);
    layout->addWidget(createReplayBar());
    layout->addWidget(m_table, 1);
    layout->addWidget(m_counter);
    connect(m_model, &BusMonitorModel::countsChanged, this, &BusMonitorPanel::updateCounter);
    connect(m_filter, &BusMonitorFilter::scanProgress, this, &BusMonitorPanel::updateCounter);
    connect(m_filterBar, &BusMonitorFilterBar::applied, this, &BusMonitorPanel::updateCounter);
    retranslate();
}

BusMonitorPanel::~BusMonitorPanel() = default;

QLayout* BusMonitorPanel::createFilterBar() {
    m_filterBar = new BusMonitorFilterBar(m_filter, this);
    m_pauseButton = button(this, "busMonitorPause", true);
    connect(m_pauseButton, &QPushButton::toggled, this, [this](bool paused) {
        m_model->setPaused(paused);
        retranslate();
    });
    m_clearButton = button(this, "busMonitorClear");
    connect(m_clearButton, &QPushButton::clicked, m_model, &BusMonitorModel::clear);

    auto* bar = new QHBoxLayout;
    bar->addWidget(m_filterBar, 1);
    bar->addWidget(m_pauseButton);
    bar->addWidget(m_clearButton);
    return bar;
}

QLayout* BusMonitorPanel::createFileBar() {
    m_recordButton = button(this, "busMonitorRecord", true);
    connect(m_recordButton, &QPushButton::clicked, this, &BusMonitorPanel::chooseRecording);
    m_openButton = button(this, "busMonitorOpenLog");
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
    auto* bar = new QHBoxLayout;
    bar->addWidget(m_recordButton);
    bar->addWidget(m_openButton);
    bar->addSpacing(12);
    bar->addWidget(m_historyLabel);
    bar->addWidget(m_history);
    bar->addStretch(); // left-aligned when it has a line of its own
    return bar;
}

QWidget* BusMonitorPanel::createReplayBar() {
    m_replayBar = new QWidget(this);
    m_replayBar->setObjectName(QStringLiteral("busMonitorReplayBar"));
    m_replayTitle = new QLabel(m_replayBar);
    m_speedBox = new QComboBox(m_replayBar);
    m_speedBox->setObjectName(QStringLiteral("busMonitorReplaySpeed"));
    for (const double speed : Speeds)
        m_speedBox->addItem(QString(), speed);
    connect(m_speedBox, &QComboBox::currentIndexChanged, this,
            [this] { m_replay->setSpeed(m_speedBox->currentData().toDouble()); });
    m_replayPauseButton = button(m_replayBar, "busMonitorReplayPause", true);
    connect(m_replayPauseButton, &QPushButton::toggled, this,
            [this](bool paused) { paused ? m_replay->pause() : m_replay->resume(); });
    m_replayProgress = new QProgressBar(m_replayBar);
    m_replayProgress->setObjectName(QStringLiteral("busMonitorReplayProgress"));
    m_replayProgress->setRange(0, 100);
    connect(m_replay, &BusMonitorReplay::progressChanged, m_replayProgress, &QProgressBar::setValue);
    connect(m_replay, &BusMonitorReplay::progressChanged, this, &BusMonitorPanel::updateReplayStatus);
    m_liveButton = button(m_replayBar, "busMonitorBackToLive");
    connect(m_liveButton, &QPushButton::clicked, this, &BusMonitorPanel::backToLive);
    m_replayStatus = new QLabel(m_replayBar);
    m_replayStatus->setObjectName(QStringLiteral("busMonitorReplayStatus"));
    auto* bar = new QHBoxLayout(m_replayBar);
    bar->setContentsMargins(0, 0, 0, 0);
    bar->addWidget(m_replayTitle);
    bar->addWidget(m_speedBox);
    bar->addWidget(m_replayPauseButton);
    bar->addWidget(m_replayProgress, 1);
    bar->addWidget(m_replayStatus);
    bar->addWidget(m_liveButton);
    m_replayBar->hide();
    return m_replayBar;
}

QTableView* BusMonitorPanel::table() const {
    return m_table;
}

void BusMonitorPanel::setBuses(connection::ConnectionBuses* buses) {
    if (m_buses)
        disconnect(m_buses, nullptr, this, nullptr);
    m_buses = buses;
    if (buses) {
        connect(buses, &connection::ConnectionBuses::busFramesSeen, this, &BusMonitorPanel::receive);
        connect(buses, &connection::ConnectionBuses::busesChanged, this, &BusMonitorPanel::takeBuses);
    }
    takeBuses();
}

// The connection's buses name the rows' buses: the station's, then the further ones by their place.
void BusMonitorPanel::takeBuses() {
    std::vector<MonitoredBus> buses;
    QStringList names;
    if (m_buses)
        for (const connection::BusInfo& info : m_buses->list()) {
            buses.push_back({info.station ? tr("station") : info.place, info.profile});
            names.append(buses.back().name);
        }
    m_model->setBuses(std::move(buses));
    m_table->fitBusColumn(names);
    showBusColumn();
}

void BusMonitorPanel::showBusColumn() {
    m_table->setBusColumnShown(m_model->busCount() > 1);
}

// Live frames go to the recording always, and to the table unless a log is shown instead.
void BusMonitorPanel::receive(int bus, const std::vector<can::CanFrame>& frames, bool outgoing) {
    const QDateTime now = QDateTime::currentDateTime();
    if (m_replay->state() == BusMonitorReplay::State::Idle)
        m_model->addFrames(frames,
                           outgoing ? BusMonitorModel::Direction::Sent : BusMonitorModel::Direction::Received,
                           now, bus);
    if (m_recorder && !m_recorder->write(frames, now, outgoing, bus)) {
        const QString file = m_recorder->fileName();
        stopRecording();
        QMessageBox::warning(this, tr("Recording stopped"),
                             tr("The frames could not be written to %1; recording stopped.").arg(file));
    }
}

void BusMonitorPanel::replayed(const std::vector<can::CanFrame>& frames, const QDateTime& time, bool outgoing,
                               int bus) {
    m_model->addFrames(frames,
                       outgoing ? BusMonitorModel::Direction::Sent : BusMonitorModel::Direction::Received,
                       time, bus);
}

void BusMonitorPanel::lineSkipped(int line, const QString& reason) {
    if (m_skippedLines.size() < MaxSkippedShown)
        m_skippedLines << tr("line %1: %2").arg(line).arg(reason);
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

// A log that cannot be read changes nothing: the table keeps what it shows.
QString BusMonitorPanel::openLog(const QString& path) {
    m_replay->setSpeed(m_speedBox->currentData().toDouble());
    const QString error = m_replay->start(path);
    if (!error.isEmpty())
        return error;
    m_model->clear();      // the first frames come on the next turn of the event loop
    m_model->setBuses({}); // the log's buses are its own: can0, can1, ...
    m_model->forgetBusContexts();
    showBusColumn();
    m_skippedLines.clear();
    m_replayPauseButton->setChecked(false);
    replayStateChanged();
    return {};
}

void BusMonitorPanel::setReplaySpeed(double factor) {
    const int index = m_speedBox->findData(factor);
    if (index >= 0)
        m_speedBox->setCurrentIndex(index);
}

void BusMonitorPanel::backToLive() {
    m_replay->stop();
    m_model->clear();
    m_model->forgetBusContexts();
    takeBuses();
}

void BusMonitorPanel::chooseLog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a candump log"), QString(),
                                                      tr("candump logs (*.log);;All files (*)"));
    if (path.isEmpty())
        return;
    const QString problem = openLog(path);
    if (!problem.isEmpty())
        QMessageBox::warning(this, tr("Log file"), tr("%1 cannot be read: %2").arg(path, problem));
}

void BusMonitorPanel::replayStateChanged() {
    m_replayBar->setVisible(m_replay->state() != BusMonitorReplay::State::Idle);
    retranslateReplay();
}

void BusMonitorPanel::setFilterText(const QString& text) {
    m_filterBar->setFilterText(text);
}

bool BusMonitorPanel::setProtocolFilter(const QString& name) {
    return m_filterBar->setProtocolFilter(name);
}

bool BusMonitorPanel::setCommandFilter(const QString& name) {
    return m_filterBar->setCommandFilter(name);
}

bool BusMonitorPanel::setLocIdFilter(const QString& text) {
    return m_filterBar->setLocIdFilter(text);
}

bool BusMonitorPanel::setHandheldFilter(const QString& text) {
    return m_filterBar->setHandheldFilter(text);
}

void BusMonitorPanel::updateCounter() {
    QString text = tr("%Ln frame(s) seen", nullptr, plural(m_model->totalFrames()));
    if (m_filter->isScanning())
        text += QStringLiteral(" · ") + tr("filtering, %1 % done").arg(m_filter->scanPercent());
    if (m_filter->isFiltering())
        text += QStringLiteral(" · ") + tr("%Ln row(s) match the filter", nullptr, m_filter->rowCount());
    for (const QString& problem : m_filterBar->problems())
        text += QStringLiteral(" · ") + problem;
    if (m_model->isPaused())
        text += QStringLiteral(" · ") +
                tr("paused, %Ln frame(s) arrived since", nullptr, plural(m_model->heldBack()));
    m_counter->setText(text);
}

void BusMonitorPanel::updateReplayStatus() {
    if (m_replay->linesSkipped() == 0)
        return m_replayStatus->clear();
    const QString first = m_replayStatus->fontMetrics().elidedText(
        m_skippedLines.value(0), Qt::ElideRight, m_replayStatus->fontMetrics().averageCharWidth() * 50);
    m_replayStatus->setText(tr("%Ln line(s) skipped; %1", nullptr, int(m_replay->linesSkipped())).arg(first));
    m_replayStatus->setToolTip(m_skippedLines.join(QLatin1Char('\n')));
}

void BusMonitorPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void BusMonitorPanel::retranslate() {
    m_pauseButton->setText(m_pauseButton->isChecked() ? tr("&Resume") : tr("&Pause"));
    m_pauseButton->setToolTip(
        tr("Stop adding rows; frames that arrive meanwhile are kept and shown on resume"));
    m_clearButton->setText(tr("C&lear"));
    m_recordButton->setText(isRecording() ? tr("Stop re&cording") : tr("Re&cord…"));
    m_recordButton->setToolTip(isRecording() ? tr("Recording to %1").arg(m_recorder->fileName())
                                             : tr("Write every frame from now on to a candump log file"));
    m_openButton->setText(tr("&Open log…"));
    m_openButton->setToolTip(tr("Play the frames of a candump log file instead of the live ones"));
    m_historyLabel->setText(tr("&Keep:"));
    m_history->setSuffix(tr(" frames"));
    m_history->setToolTip(tr("How many frames the table keeps; older ones are dropped"));
    emit m_model->headerDataChanged(Qt::Horizontal, 0, BusMonitorModel::ColumnCount - 1);
    if (m_buses && m_replay->state() == BusMonitorReplay::State::Idle)
        takeBuses(); // the station's bus is named in the language
    retranslateReplay();
    updateCounter();
}

void BusMonitorPanel::retranslateReplay() {
    const QString file = QFileInfo(m_replay->fileName()).fileName();
    const bool finished = m_replay->state() == BusMonitorReplay::State::Finished;
    m_replayTitle->setText(finished ? tr("Replayed %1").arg(file) : tr("Replaying %1").arg(file));
    m_speedBox->setItemText(0, tr("1× (as recorded)"));
    m_speedBox->setItemText(1, tr("2×"));
    m_speedBox->setItemText(2, tr("10×"));
    m_speedBox->setItemText(3, tr("As fast as possible"));
    m_speedBox->setToolTip(tr("How fast the log plays"));
    m_replayPauseButton->setText(m_replayPauseButton->isChecked() ? tr("Res&ume replay")
                                                                  : tr("Pa&use replay"));
    m_replayPauseButton->setEnabled(!finished);
    m_liveButton->setText(tr("Back to li&ve"));
    m_liveButton->setToolTip(tr("Stop the replay, clear the table and show the station's frames again"));
    updateReplayStatus();
}

} // namespace stellwerk::ui
