#include "monitor/BusMonitorFilterBar.h"

#include "busreading/FrameDescription.h"
#include "monitor/BusMonitorFilter.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPalette>
#include <QTimer>

namespace stellwerk::ui {
namespace {

constexpr int TypingPauseMs = 200;

QString latin1(std::string_view text) {
    return QString::fromLatin1(text.data(), qsizetype(text.size()));
}

} // namespace

BusMonitorFilterBar::BusMonitorFilterBar(BusMonitorFilter* filter, QWidget* parent)
    : QWidget(parent), m_filter(filter), m_delay(new QTimer(this)) {
    m_delay->setSingleShot(true);
    m_delay->setInterval(TypingPauseMs);
    connect(m_delay, &QTimer::timeout, this, &BusMonitorFilterBar::apply);
    m_textEdit = lineEdit("busMonitorFilter");
    m_protocolBox = protocolBox();
    m_handheldEdit = lineEdit("busMonitorHandheld");
    m_handheldEdit->setMaximumWidth(fontMetrics().horizontalAdvance(QStringLiteral("43 or KS MS1")));
    m_commandBox = commandBox();
    m_locIdEdit = lineEdit("busMonitorLocId");
    m_locIdEdit->setMaximumWidth(fontMetrics().horizontalAdvance(QStringLiteral("0xC003 or dcc 3")));
    auto* bar = new QHBoxLayout(this);
    bar->setContentsMargins(0, 0, 0, 0);
    bar->addWidget(m_textEdit, 1);
    bar->addWidget(m_protocolBox);
    bar->addWidget(m_handheldEdit);
    bar->addWidget(m_commandBox);
    bar->addWidget(m_locIdEdit);
    retranslate();
}

QLineEdit* BusMonitorFilterBar::lineEdit(const char* name) {
    auto* edit = new QLineEdit(this);
    edit->setObjectName(QLatin1String(name));
    edit->setClearButtonEnabled(true);
    connect(edit, &QLineEdit::textChanged, m_delay, qOverload<>(&QTimer::start));
    return edit;
}

// The protocols a frame may belong to, all first; the data is the protocol's short name ("cs2").
QComboBox* BusMonitorFilterBar::protocolBox() {
    auto* box = new QComboBox(this);
    box->setObjectName(QStringLiteral("busMonitorProtocol"));
    box->addItem(QString(), QString());
    for (std::size_t protocol = 0; protocol < busreading::ProtocolCount; ++protocol)
        box->addItem(QString(), latin1(busreading::protocolName(busreading::Protocol(protocol))));
    box->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(box, &QComboBox::currentIndexChanged, this, &BusMonitorFilterBar::apply);
    return box;
}

// Every command of the protocols of a station's bus (CS2, then M-CAN), all first.
QComboBox* BusMonitorFilterBar::commandBox() {
    auto* box = new QComboBox(this);
    box->setObjectName(QStringLiteral("busMonitorCommand"));
    box->addItem(QString());
    for (const std::string_view name : busreading::messageNames(busreading::BusProfile::centralStation()))
        box->addItem(latin1(name));
    box->setMaxVisibleItems(20);
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(16);
    connect(box, &QComboBox::currentIndexChanged, this, &BusMonitorFilterBar::apply);
    return box;
}

void BusMonitorFilterBar::setFilterText(const QString& text) {
    m_textEdit->setText(text);
    apply();
}

bool BusMonitorFilterBar::setProtocolFilter(const QString& name) {
    const int index = m_protocolBox->findData(name);
    if (index < 0)
        return false;
    m_protocolBox->setCurrentIndex(index);
    apply();
    return true;
}

bool BusMonitorFilterBar::setCommandFilter(const QString& name) {
    const int index = name.isEmpty() ? 0 : m_commandBox->findText(name);
    if (index < 0)
        return false;
    m_commandBox->setCurrentIndex(index);
    apply();
    return true;
}

bool BusMonitorFilterBar::setLocIdFilter(const QString& text) {
    m_locIdEdit->setText(text);
    apply();
    return m_locIdValid;
}

bool BusMonitorFilterBar::setHandheldFilter(const QString& text) {
    m_handheldEdit->setText(text);
    apply();
    return m_handheldValid;
}

QStringList BusMonitorFilterBar::problems() const {
    QStringList problems;
    if (!m_locIdValid)
        problems << tr("the Loc-ID is not understood; write e.g. 0xC003, 49155 or dcc 3");
    if (!m_handheldValid)
        problems << tr("the handheld is not understood; write its node, e.g. 43, or its name");
    return problems;
}

void BusMonitorFilterBar::apply() {
    m_delay->stop();
    const QString locIdText = m_locIdEdit->text().trimmed();
    const auto locId = BusMonitorFilter::parseLocId(locIdText);
    m_locIdValid = locIdText.isEmpty() || locId.has_value();
    showValidity(m_locIdEdit, m_locIdValid);
    const QString handheldText = m_handheldEdit->text().trimmed();
    const auto handheld = busreading::HandheldReference::parse(handheldText.toStdString());
    m_handheldValid = handheldText.isEmpty() || handheld.has_value();
    showValidity(m_handheldEdit, m_handheldValid);
    const int protocol = m_protocolBox->currentIndex() - 1;
    m_filter->setProtocol(protocol < 0 ? std::nullopt : std::optional(busreading::Protocol(protocol)));
    m_filter->setHandheld(handheld);
    m_filter->setFilters(m_commandBox->currentIndex() > 0 ? m_commandBox->currentText() : QString(), locId,
                         m_textEdit->text().trimmed());
    emit applied();
}

// Text the filter cannot read turns red, in light and dark themes alike.
void BusMonitorFilterBar::showValidity(QLineEdit* edit, bool valid) {
    QPalette colours = palette();
    if (!valid) {
        const bool dark = colours.color(QPalette::Base).lightness() < 128;
        colours.setColor(QPalette::Text, QColor::fromHsv(0, dark ? 150 : 230, dark ? 255 : 190));
    }
    edit->setPalette(colours);
}

void BusMonitorFilterBar::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void BusMonitorFilterBar::retranslate() {
    m_textEdit->setPlaceholderText(tr("Find text, e.g. speed=0"));
    m_protocolBox->setItemText(0, tr("All protocols"));
    m_protocolBox->setItemText(1 + int(busreading::Protocol::Cs2), tr("CS2"));
    m_protocolBox->setItemText(1 + int(busreading::Protocol::Mcan), tr("M-CAN"));
    m_protocolBox->setItemText(1 + int(busreading::Protocol::Ro), tr("RO"));
    m_protocolBox->setItemText(1 + int(busreading::Protocol::Orc), tr("OpenRailCAN"));
    m_protocolBox->setItemText(1 + int(busreading::Protocol::Foreign), tr("Foreign"));
    m_protocolBox->setToolTip(tr("Show only frames of one protocol; foreign frames belong to none that is "
                                 "expected on their bus"));
    m_handheldEdit->setPlaceholderText(tr("Handheld"));
    m_handheldEdit->setToolTip(tr("Show only the M-CAN frames of one MS1 handheld: its node (43, or its "
                                  "master's 42) or the name it sent"));
    m_commandBox->setItemText(0, tr("All commands"));
    m_commandBox->setToolTip(tr("Show only frames of one command"));
    m_locIdEdit->setPlaceholderText(tr("Loc-ID"));
    m_locIdEdit->setToolTip(tr("Show only frames for one Loc-ID: 0xC003, 49155 or a protocol and address "
                               "such as dcc 3, mfx 5, mm2 80"));
}

} // namespace stellwerk::ui
