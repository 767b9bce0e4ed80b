#include "programming/ProgrammingPanel.h"

#include "common/SideBySide.h"
#include "model/Railway.h"
#include "programming/FoundDecoders.h"
#include "programming/ProgrammingResultText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stellwerk::ui {

namespace {

using Outcome = model::ProgrammingResult::Outcome;
using Problem = model::ProgrammingResult::Problem;
using Task = model::ProgrammingResult::Task;

using Limits = model::Programmer;
enum Label {
    LocomotiveLabel,
    DecoderLabel,
    CvLabel,
    IndexLabel,
    ValueLabel,
    TrackLabel,
    ModeLabel,
    BitLabel,
    LabelCount
};

template <class T>
T* named(T* widget, const char* name) {
    widget->setObjectName(QLatin1String(name));
    return widget;
}

} // namespace

ProgrammingPanel::ProgrammingPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("programmingPanel"));
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(buildRegistration(), 1);
    layout->addWidget(buildCvProgramming(), 1);
    SideBySide::arrange(this, layout, 760); // stacked in a side panel
    retranslate();
    updateEnabled();
}

QGroupBox* ProgrammingPanel::buildRegistration() {
    m_registration = named(new QGroupBox(this), "mfxRegistration");
    m_search = named(new QPushButton(m_registration), "searchDecoders");
    m_progress = named(new QProgressBar(m_registration), "searchProgress");
    m_progress->setRange(0, model::Programmer::DiscoverySteps);
    m_progress->setValue(0);
    m_progress->setFormat(QStringLiteral("%v / %m"));
    m_searchText = named(new QLabel(m_registration), "searchText");
    m_searchText->setWordWrap(true);
    m_decoders = new FoundDecoders(m_registration);
    m_sidLabel = new QLabel(m_registration);
    m_sid = named(new QSpinBox(m_registration), "bindSid");
    m_sid->setRange(1, Limits::MaxSid);
    m_register = named(new QPushButton(m_registration), "registerDecoder");
    auto* searchLine = new QHBoxLayout;
    searchLine->addWidget(m_search);
    searchLine->addWidget(m_progress, 1);
    auto* bindLine = new QHBoxLayout;
    bindLine->addWidget(m_sidLabel);
    bindLine->addWidget(m_sid);
    bindLine->addStretch(1);
    bindLine->addWidget(m_register);
    auto* box = new QVBoxLayout(m_registration);
    box->addLayout(searchLine);
    box->addWidget(m_searchText);
    box->addWidget(m_decoders, 1);
    box->addLayout(bindLine);
    connect(m_search, &QPushButton::clicked, this, &ProgrammingPanel::search);
    connect(m_register, &QPushButton::clicked, this, &ProgrammingPanel::registerDecoder);
    connect(m_decoders, &QTableWidget::itemSelectionChanged, this, &ProgrammingPanel::updateEnabled);
    return m_registration;
}

// The fields of a CV request; the labels are named in retranslate().
void ProgrammingPanel::createCvFields() {
    QWidget* box = m_programming;
    m_locomotive = named(new QComboBox(box), "cvLocomotive");
    m_protocol = named(new QComboBox(box), "cvProtocol");
    for (const cs2::Protocol protocol : Limits::Protocols)
        m_protocol->addItem(QString(), int(protocol));
    m_address = named(new QSpinBox(box), "cvAddress");
    m_address->setRange(0, Limits::MaxAddress);
    m_cv = named(new QSpinBox(box), "cvNumber");
    m_cv->setRange(1, Limits::MaxCv);
    m_index = named(new QSpinBox(box), "cvIndex");
    m_index->setRange(0, Limits::MaxIndex);
    m_value = named(new QSpinBox(box), "cvValue");
    m_value->setRange(0, Limits::MaxValue);
    m_track = named(new QComboBox(box), "cvTrack");
    m_track->addItems({QString(), QString()});
    m_mode = named(new QComboBox(box), "cvMode");
    m_mode->addItems({QString(), QString(), QString()});
    m_bit = named(new QSpinBox(box), "cvBit");
    m_bit->setRange(0, Limits::MaxBit);
    m_bitOn = named(new QCheckBox(box), "cvBitOn");
    m_protocolNote = named(new QLabel(box), "cvNote");
    m_protocolNote->setWordWrap(true);
    m_protocolNote->setEnabled(false);
    m_read = named(new QPushButton(box), "readCv");
    m_write = named(new QPushButton(box), "writeCv");
    m_result = named(new QLabel(box), "cvResult");
    m_result->setWordWrap(true);
    m_result->setMinimumHeight(m_result->fontMetrics().height() * 3);
    m_result->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    for (int i = 0; i < LabelCount; ++i)
        m_labels << new QLabel(box);
}

QGridLayout* ProgrammingPanel::cvGrid() {
    auto* grid = new QGridLayout;
    const auto row = [&](int line, Label label, QWidget* first, QWidget* second = nullptr,
                         Label secondLabel = LabelCount) {
        grid->addWidget(m_labels[label], line, 0);
        grid->addWidget(first, line, 1);
        if (secondLabel != LabelCount)
            grid->addWidget(m_labels[secondLabel], line, 2, Qt::AlignRight);
        if (second)
            grid->addWidget(second, line, 3);
    };
    grid->addWidget(m_labels[LocomotiveLabel], 0, 0);
    grid->addWidget(m_locomotive, 0, 1, 1, 3);
    auto* decoder = new QHBoxLayout;
    decoder->addWidget(m_protocol, 1);
    decoder->addWidget(m_address, 1);
    grid->addWidget(m_labels[DecoderLabel], 1, 0);
    grid->addLayout(decoder, 1, 1);
    row(2, CvLabel, m_cv, m_index, IndexLabel);
    row(3, ValueLabel, m_value);
    row(4, TrackLabel, m_track);
    row(5, ModeLabel, m_mode, m_bit, BitLabel);
    grid->addWidget(m_bitOn, 6, 3); // under the bit: the line stays narrow enough for a side panel
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(3, 1);
    return grid;
}

QGroupBox* ProgrammingPanel::buildCvProgramming() {
    m_programming = named(new QGroupBox(this), "cvProgramming");
    createCvFields();
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_read);
    buttons->addWidget(m_write);
    auto* layout = new QVBoxLayout(m_programming);
    layout->addLayout(cvGrid());
    layout->addWidget(m_protocolNote);
    layout->addLayout(buttons);
    layout->addWidget(m_result);
    layout->addStretch(1);
    connect(m_locomotive, &QComboBox::activated, this, &ProgrammingPanel::locomotiveChosen);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &ProgrammingPanel::protocolChosen);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &ProgrammingPanel::protocolChosen);
    connect(m_read, &QPushButton::clicked, this, &ProgrammingPanel::readCv);
    connect(m_write, &QPushButton::clicked, this, &ProgrammingPanel::writeCv);
    return m_programming;
}

void ProgrammingPanel::setRailway(model::Railway* railway) {
    if (m_railway) {
        disconnect(m_railway, nullptr, this, nullptr);
        disconnect(&m_railway->programmer(), nullptr, this, nullptr);
    }
    m_railway = railway;
    if (m_railway) {
        connect(m_railway, &model::Railway::loaded, this, &ProgrammingPanel::fillLocomotives);
        connect(m_railway, &QObject::destroyed, this, [this] { setRailway(nullptr); });
        connect(&m_railway->programmer(), &model::Programmer::discoveryProgress, this,
                &ProgrammingPanel::progressed);
        connect(&m_railway->programmer(), &model::Programmer::finished, this, &ProgrammingPanel::finished);
    }
    m_decoders->clearDecoders();
    m_progress->setValue(0);
    instruct({});
    showResult({}, false);
    fillLocomotives();
    updateEnabled();
}

void ProgrammingPanel::fillLocomotives() {
    const QString chosen = m_locomotive->currentText();
    m_locomotive->clear();
    m_locomotive->addItem(tr("(address below)"), QVariant());
    if (m_railway)
        for (const model::Locomotive& loco : m_railway->state().locomotives().items())
            m_locomotive->addItem(loco.displayName(), loco.id().value());
    const int again = m_locomotive->findText(chosen);
    m_locomotive->setCurrentIndex(again < 0 ? 0 : again);
    m_sid->setValue(suggestedSid());
}

bool ProgrammingPanel::chooseLocomotive(const QString& name) {
    const int index = m_locomotive->findText(name);
    if (index < 0)
        return false;
    m_locomotive->setCurrentIndex(index);
    locomotiveChosen();
    return true;
}

// A locomotive from the list fills in its protocol and address.
void ProgrammingPanel::locomotiveChosen() {
    const QVariant id = m_locomotive->currentData();
    if (!id.isValid())
        return;
    const cs2::LocId loco(id.toUInt());
    const int protocol = m_protocol->findData(int(loco.protocol()));
    if (protocol >= 0)
        m_protocol->setCurrentIndex(protocol);
    m_address->setValue(int(loco.address()));
}

void ProgrammingPanel::protocolChosen() {
    const auto protocol = cs2::Protocol(m_protocol->currentData().toInt());
    m_index->setEnabled(protocol == cs2::Protocol::Mfx);
    if (protocol != cs2::Protocol::Mfx)
        m_index->setValue(0);
    const bool dcc = protocol == cs2::Protocol::Dcc;
    m_mode->setEnabled(dcc);
    if (!dcc)
        m_mode->setCurrentIndex(0);
    const bool bitMode = dcc && m_mode->currentIndex() == int(cs2::DccProgrammingMode::Bit);
    m_bit->setEnabled(bitMode);
    m_bitOn->setEnabled(bitMode);
    m_value->setEnabled(!bitMode);
    switch (protocol) {
    case cs2::Protocol::Mm2:
        m_protocolNote->setText(tr("MM2 decoders can be written (CV 1–256) but not read back."));
        break;
    case cs2::Protocol::Mfx:
        m_protocolNote->setText(tr("mfx: CV 1–1023 with an index (read 0–63, write 1–63), on either track."));
        break;
    case cs2::Protocol::Sx1:
        m_protocolNote->setText(tr("SX1: values 1–5 (address, top speed, acceleration, pulse width, stop "
                                   "sections), programming track only."));
        break;
    default:
        m_protocolNote->setText(tr("DCC: CV 1–1023; read on the programming track, write on either track."));
        break;
    }
}

std::optional<model::CvTarget> ProgrammingPanel::target() const {
    const auto loco = cs2::LocId::fromAddress(cs2::Protocol(m_protocol->currentData().toInt()),
                                              std::uint32_t(m_address->value()));
    if (!loco)
        return std::nullopt;
    return model::CvTarget{*loco, std::uint16_t(m_cv->value()), std::uint8_t(m_index->value())};
}

void ProgrammingPanel::search() {
    if (!m_railway)
        return;
    m_searchFailed = false;
    m_progress->setValue(0);
    instruct([] { return tr("Searching the track for new mfx decoders…"); });
    m_railway->programmer().discover();
    updateEnabled();
}

void ProgrammingPanel::progressed(int range, quint32 uidSoFar) {
    m_progress->setValue(range);
    instruct([range, uidSoFar] {
        return tr("Searching: %1 of %2 bits of the decoder's UID known (%3)")
            .arg(range)
            .arg(model::Programmer::DiscoverySteps)
            .arg(FoundDecoders::uidText(uidSoFar));
    });
}

void ProgrammingPanel::registerDecoder() {
    const std::optional<std::uint32_t> uid = m_decoders->selectedUid();
    if (!m_railway || !uid)
        return;
    m_railway->programmer().bind(*uid, std::uint16_t(m_sid->value()));
    updateEnabled();
}

void ProgrammingPanel::readCv() {
    const std::optional<model::CvTarget> cv = target();
    if (!m_railway)
        return;
    if (!cv) {
        showResult([] { return tr("This address does not exist for the chosen protocol."); }, true);
        return;
    }
    showResult([number = cv->cv] { return tr("Reading CV %1…").arg(number); }, false);
    m_railway->programmer().readCv(*cv);
    updateEnabled();
}

void ProgrammingPanel::writeCv() {
    const std::optional<model::CvTarget> cv = target();
    if (!m_railway)
        return;
    if (!cv) {
        showResult([] { return tr("This address does not exist for the chosen protocol."); }, true);
        return;
    }
    model::CvWrite write;
    write.target = *cv;
    write.mode = cs2::DccProgrammingMode(m_mode->currentIndex());
    write.value = write.mode == cs2::DccProgrammingMode::Bit
                      ? model::CvWrite::bitValue(m_bit->value(), m_bitOn->isChecked())
                      : std::uint8_t(m_value->value());
    write.track =
        m_track->currentIndex() == 1 ? model::ProgrammingTrack::Main : model::ProgrammingTrack::Programming;
    showResult([number = cv->cv] { return tr("Writing CV %1…").arg(number); }, false);
    m_railway->programmer().writeCv(write);
    updateEnabled();
}

void ProgrammingPanel::finished(const model::ProgrammingResult& result) {
    switch (result.task) {
    case Task::Discovery:
        discoveryFinished(result);
        break;
    case Task::Bind:
        bindFinished(result);
        break;
    case Task::Verify:
        verifyFinished(result);
        break;
    case Task::ReadCv:
        if (result.succeeded() && result.value)
            m_value->setValue(*result.value); // ready to be changed and written back
        [[fallthrough]];
    case Task::WriteCv:
        showResult(
            [result] {
                return result.succeeded() ? ProgrammingResultText::cv(result)
                                          : ProgrammingResultText::failure(result);
            },
            !result.succeeded());
        break;
    }
    updateEnabled();
}

void ProgrammingPanel::discoveryFinished(const model::ProgrammingResult& result) {
    m_searchFailed = !result.succeeded() && result.outcome != Outcome::NotFound;
    if (result.outcome == Outcome::NotFound) {
        m_progress->setValue(m_progress->maximum());
        instruct([] {
            return tr("No new mfx decoder answered. Decoders that are registered already take no part.");
        });
        return;
    }
    if (!result.succeeded()) {
        instruct([result] { return ProgrammingResultText::failure(result); });
        return;
    }
    m_decoders->show(result.mfxUid, [] { return tr("found"); });
    instruct([uid = result.mfxUid] {
        return tr("Found mfx decoder %1. Choose a SID and press Register; search again for more.")
            .arg(FoundDecoders::uidText(uid));
    });
    m_sid->setValue(suggestedSid());
}

void ProgrammingPanel::bindFinished(const model::ProgrammingResult& result) {
    if (!result.succeeded()) {
        m_decoders->show(result.mfxUid, [result] { return ProgrammingResultText::failure(result); });
        return;
    }
    m_decoders->show(result.mfxUid,
                     [sid = result.sid] { return tr("bound to SID %1, verifying…").arg(sid); });
    if (m_railway)
        m_railway->programmer().verify(result.mfxUid, result.sid);
}

void ProgrammingPanel::verifyFinished(const model::ProgrammingResult& result) {
    if (!result.succeeded()) {
        m_decoders->show(result.mfxUid, [result] {
            return result.outcome == Outcome::Refused ? tr("does not answer under SID %1").arg(result.sid)
                                                      : ProgrammingResultText::failure(result);
        });
        return;
    }
    m_decoders->show(result.mfxUid, [sid = result.sid] { return tr("registered on SID %1").arg(sid); });
    instruct([result] {
        return tr("Registered mfx decoder %1 on SID %2. It is a locomotive of the list now: name it and save "
                  "it there; search again for more.")
            .arg(FoundDecoders::uidText(result.mfxUid))
            .arg(result.sid);
    });
    m_lastBoundSid = std::max(m_lastBoundSid, result.sid);
    m_sid->setValue(suggestedSid());
    emit decoderBound(result.mfxUid, result.sid);
}

// The text above the found decoders: what happens, what to do next; made again in another language.
void ProgrammingPanel::instruct(std::function<QString()> text) {
    m_instruction = std::move(text);
    m_searchText->setText(m_instruction ? m_instruction() : QString());
}

QTableWidget* ProgrammingPanel::decoderTable() const {
    return m_decoders;
}

QString ProgrammingPanel::searchText() const {
    return m_searchText->text();
}

QString ProgrammingPanel::resultText() const {
    return m_result->text();
}

void ProgrammingPanel::showResult(std::function<QString()> text, bool problem) {
    m_resultSaid = std::move(text);
    m_result->setText(m_resultSaid ? m_resultSaid() : QString());
    m_result->setStyleSheet(problem ? QStringLiteral("QLabel { color: #c82c2c; font-weight: bold; }")
                                    : QStringLiteral("QLabel { font-weight: bold; }"));
}

std::uint16_t ProgrammingPanel::suggestedSid() const {
    std::uint32_t highest = m_lastBoundSid;
    if (m_railway)
        for (const model::Locomotive& loco : m_railway->state().locomotives().items())
            if (loco.id().protocol() == cs2::Protocol::Mfx)
                highest = std::max(highest, loco.id().address());
    return std::uint16_t(std::min<std::uint32_t>(highest + 1, Limits::MaxSid));
}

void ProgrammingPanel::updateEnabled() {
    const bool ready = m_railway && !m_railway->programmer().busy();
    m_search->setEnabled(ready);
    m_register->setEnabled(ready && !m_decoders->selectedItems().isEmpty());
    m_read->setEnabled(ready);
    m_write->setEnabled(ready);
    if (!m_railway)
        instruct([] { return tr("No station connected."); });
}

void ProgrammingPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ProgrammingPanel::retranslate() {
    m_registration->setTitle(tr("New mfx decoders"));
    m_programming->setTitle(tr("CV programming"));
    m_search->setText(tr("Search"));
    m_search->setToolTip(tr("The station searches the track for one mfx decoder that is not registered yet"));
    m_sidLabel->setText(tr("SID:"));
    m_register->setText(tr("Register"));
    m_register->setToolTip(tr("Binds the selected decoder to the SID, then checks that it answers"));
    const QStringList labels{tr("Locomotive:"), tr("Decoder:"), tr("CV:"),       tr("Index:"),
                             tr("Value:"),      tr("Track:"),   tr("DCC mode:"), tr("Bit:")};
    for (int i = 0; i < LabelCount; ++i)
        m_labels[i]->setText(labels[i]);
    m_protocol->setItemText(0, tr("mfx SID"));
    m_protocol->setItemText(1, tr("DCC"));
    m_protocol->setItemText(2, tr("MM2"));
    m_protocol->setItemText(3, tr("SX1"));
    m_track->setItemText(0, tr("programming track"));
    m_track->setItemText(1, tr("main track (write only)"));
    m_mode->setItemText(0, tr("direct"));
    m_mode->setItemText(1, tr("register"));
    m_mode->setItemText(2, tr("bit"));
    m_bitOn->setText(tr("set"));
    m_read->setText(tr("Read"));
    m_write->setText(tr("Write"));
    if (m_locomotive->count() > 0)
        m_locomotive->setItemText(0, tr("(address below)"));
    protocolChosen();
    updateEnabled();
    instruct(m_instruction);
    if (m_resultSaid)
        m_result->setText(m_resultSaid());
}

} // namespace stellwerk::ui
