#include "monitor/FrameDecoderPanel.h"

#include "busreading/BusContext.h"
#include "can/FrameText.h"

#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace stellwerk::ui {
namespace {

enum Column { LineColumn, FrameColumn, MessageColumn, DetailsColumn };

// Captures larger than this are refused rather than freezing the window.
constexpr qint64 MaxCaptureBytes = 8 * 1024 * 1024;

bool isSkippable(const QString& line) {
    const QString trimmed = line.trimmed();
    return trimmed.isEmpty() || trimmed.startsWith(QLatin1Char('#'));
}

QTreeWidgetItem* errorItem(int lineNumber, const QString& frame, const QString& message,
                           const QString& details) {
    auto* item = new QTreeWidgetItem({QString::number(lineNumber), frame, message, details});
    for (int column = 0; column <= DetailsColumn; ++column)
        item->setForeground(column, QColor(0xB0, 0x1C, 0x1C));
    item->setToolTip(DetailsColumn, details);
    return item;
}

} // namespace

FrameDecoderPanel::FrameDecoderPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("frameDecoderPanel"));
    const QFont fixed = QFontDatabase::systemFont(QFontDatabase::FixedFont);

    m_hint = new QLabel(this);
    m_hint->setWordWrap(true);
    m_input = new QPlainTextEdit(this);
    m_input->setObjectName(QStringLiteral("frameInput"));
    m_input->setFont(fixed);
    m_input->setLineWrapMode(QPlainTextEdit::NoWrap);

    m_results = new QTreeWidget(this);
    m_results->setObjectName(QStringLiteral("frameResults"));
    m_results->setRootIsDecorated(false);
    m_results->setUniformRowHeights(true);
    m_results->setAlternatingRowColors(true);
    m_results->setFont(fixed);
    m_results->header()->setStretchLastSection(true);

    m_openButton = new QPushButton(this);
    m_openButton->setObjectName(QStringLiteral("openCaptureButton"));
    m_clearButton = new QPushButton(this);
    m_clearButton->setObjectName(QStringLiteral("clearButton"));
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("decoderSummary"));

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_openButton);
    buttons->addWidget(m_clearButton);
    buttons->addStretch();
    buttons->addWidget(m_summary);

    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_input);
    splitter->addWidget(m_results);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 3);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_hint);
    layout->addLayout(buttons);
    layout->addWidget(splitter, 1);

    // Decode shortly after typing stops, not on every key press.
    m_refreshTimer = new QTimer(this);
    m_refreshTimer->setSingleShot(true);
    m_refreshTimer->setInterval(200);
    connect(m_refreshTimer, &QTimer::timeout, this, &FrameDecoderPanel::refresh);
    connect(m_input, &QPlainTextEdit::textChanged, m_refreshTimer, qOverload<>(&QTimer::start));
    connect(m_openButton, &QPushButton::clicked, this, &FrameDecoderPanel::openCapture);
    connect(m_clearButton, &QPushButton::clicked, m_input, &QPlainTextEdit::clear);

    retranslate();
    refresh();
}

void FrameDecoderPanel::setInput(const QString& text) {
    m_input->setPlainText(text);
    m_refreshTimer->stop();
    refresh();
}

// The lines are one bus, read in order: what earlier frames revealed (an MS1's handles) names later ones.
void FrameDecoderPanel::refresh() {
    const busreading::BusProfile station = busreading::BusProfile::centralStation();
    busreading::BusContext context;
    QList<QTreeWidgetItem*> items;
    int frames = 0, errors = 0;
    const QStringList lines = m_input->toPlainText().split(QLatin1Char('\n'));
    for (int i = 0; i < lines.size(); ++i) {
        if (isSkippable(lines[i]))
            continue;
        ++frames;
        const auto parsed = can::parseFrame(lines[i].toStdString());
        if (!parsed) {
            ++errors;
            items.append(errorItem(i + 1, lines[i].trimmed(), tr("unreadable"),
                                   QString::fromStdString(parsed.error())));
            continue;
        }
        const busreading::FrameDescription description = context.read(parsed->frame, station);
        const QString frame = QString::fromStdString(description.frameText());
        QString message = QString::fromStdString(std::string(description.name()));
        if (description.isResponse())
            message = tr("%1 (response)").arg(message);
        const QString details = QString::fromStdString(description.detailText());
        if (!description.decoded()) {
            ++errors;
            items.append(errorItem(i + 1, frame, message, details));
            continue;
        }
        auto* item = new QTreeWidgetItem({QString::number(i + 1), frame, message, details});
        item->setToolTip(DetailsColumn, details);
        items.append(item);
    }
    m_results->clear();
    m_results->addTopLevelItems(items); // one insert for the whole batch
    for (int column = LineColumn; column < DetailsColumn; ++column)
        m_results->resizeColumnToContents(column);
    updateSummary(frames, errors);
}

void FrameDecoderPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void FrameDecoderPanel::openCapture() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open capture"), QString(),
                                                      tr("Captures (*.log *.txt *.can);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const QString error = loadCapture(path); !error.isEmpty())
        QMessageBox::warning(this, tr("Open capture"), error);
}

QString FrameDecoderPanel::loadCapture(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return tr("%1 could not be read: %2").arg(path, file.errorString());
    if (file.size() > MaxCaptureBytes)
        return tr("%1 is larger than %2 MB; open a shorter excerpt.").arg(path).arg(MaxCaptureBytes >> 20);
    setInput(QString::fromUtf8(file.readAll()));
    return {};
}

void FrameDecoderPanel::retranslate() {
    m_hint->setText(
        tr("Paste CAN frames of the CS2 or of MS1 handhelds (M-CAN), one per line, as written in "
           "the Märklin documents (00004711 5 00 00 00 00 00), by candump (00004711#0000000000) or "
           "as 13-byte network frames in hex. Lines starting with # are ignored; the lines are "
           "read in order, as one bus."));
    m_input->setPlaceholderText(tr("00084711 6 00 00 C0 03 01 20"));
    m_results->setHeaderLabels({tr("Line"), tr("Frame"), tr("Message"), tr("Details")});
    m_openButton->setText(tr("&Open capture…"));
    m_clearButton->setText(tr("C&lear"));
    updateSummary(m_frames, m_errors);
}

void FrameDecoderPanel::updateSummary(int frames, int errors) {
    m_frames = frames;
    m_errors = errors;
    m_summary->setText(errors == 0 ? tr("%n frame(s)", nullptr, frames)
                                   : tr("%n frame(s), %1 not decodable", nullptr, frames).arg(errors));
}

} // namespace stellwerk::ui
