#include "locomotives/LocomotiveForm.h"

#include "common/FunctionIcons.h"
#include "common/LocomotivePictureBook.h"
#include "locomotives/LocomotiveFileModel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stellwerk::ui {

namespace {

using cs2config::FunctionTrigger;
using cs2config::LocomotiveDecoder;

constexpr LocomotiveDecoder Decoders[] = {LocomotiveDecoder::Mfx,     LocomotiveDecoder::Mm2Prg,
                                          LocomotiveDecoder::Mm2Dil8, LocomotiveDecoder::Mmm2Lok,
                                          LocomotiveDecoder::MmPrg,   LocomotiveDecoder::Dcc,
                                          LocomotiveDecoder::Sx1};
// Unknown: a `..dauer` value the file holds and Stellwerk does not understand; kept as it is.
constexpr FunctionTrigger Triggers[] = {FunctionTrigger::Latching, FunctionTrigger::Momentary,
                                        FunctionTrigger::Timed, FunctionTrigger::Unknown};
// The CS2's icon number, then what it shows (our drawing and its name), the trigger and the time.
enum FunctionColumn { IconColumn, PictureColumn, TriggerColumn, DurationColumn, FunctionColumns };
constexpr int PictureSize = 20;
constexpr QSize LocomotivePictureBox(132, 44);

} // namespace

LocomotiveForm::LocomotiveForm(QWidget* parent)
    : QWidget(parent), m_form(new QFormLayout), m_name(new QLineEdit(this)), m_decoder(new QComboBox(this)),
      m_address(new QSpinBox(this)), m_addressRange(new QLabel(this)), m_nameLabel(new QLabel(this)),
      m_decoderLabel(new QLabel(this)), m_addressLabel(new QLabel(this)), m_picture(new QLabel(this)),
      m_pictureName(new QLabel(this)),
      m_functions(new QTableWidget(cs2config::LocomotiveEditor::MaxFunctions, FunctionColumns, this)) {
    setObjectName(QStringLiteral("locomotiveForm"));
    m_name->setObjectName(QStringLiteral("locomotiveName"));
    m_decoder->setObjectName(QStringLiteral("locomotiveDecoder"));
    m_address->setObjectName(QStringLiteral("locomotiveAddress"));
    m_functions->setObjectName(QStringLiteral("locomotiveFunctions"));
    for (const LocomotiveDecoder decoder : Decoders)
        m_decoder->addItem(QString(), int(decoder));
    m_address->setRange(0, int(cs2config::LocomotiveEditor::MaxAddress)); // wider than any decoder: the
                                                                          // editor explains what is allowed
    m_addressRange->setEnabled(false);
    auto* address = new QHBoxLayout;
    address->addWidget(m_address);
    address->addWidget(m_addressRange, 1);
    m_form->addRow(m_nameLabel, m_name);
    m_form->addRow(m_decoderLabel, m_decoder);
    m_form->addRow(m_addressLabel, address);
    m_picture->setObjectName(QStringLiteral("locomotivePicture"));
    m_picture->setFixedSize(LocomotivePictureBox);
    m_picture->setAlignment(Qt::AlignCenter);
    m_pictureName->setEnabled(false);
    m_pictureName->setAlignment(Qt::AlignHCenter | Qt::AlignTop);
    m_pictureName->setMaximumWidth(LocomotivePictureBox.width());
    buildFunctionRows();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    // The picture beside the fields, its name below it: no extra row in a short window.
    auto* picture = new QVBoxLayout;
    picture->addWidget(m_picture);
    picture->addWidget(m_pictureName);
    picture->addStretch(1);
    auto* top = new QHBoxLayout;
    top->addLayout(m_form, 1);
    top->addLayout(picture);
    layout->addLayout(top);
    layout->addWidget(m_functions, 1);
    connect(m_name, &QLineEdit::textEdited, this, &LocomotiveForm::edited);
    connect(m_decoder, &QComboBox::currentIndexChanged, this, [this] {
        showAddressRange();
        emit edited();
    });
    connect(m_address, &QSpinBox::valueChanged, this, &LocomotiveForm::edited);
    retranslate();
}

void LocomotiveForm::setPictures(LocomotivePictureBook* pictures) {
    if (m_pictures)
        m_pictures->disconnect(this);
    m_pictures = pictures;
    if (m_pictures)
        connect(m_pictures, &LocomotivePictureBook::changed, this, &LocomotiveForm::showLocomotivePicture);
    showLocomotivePicture();
}

void LocomotiveForm::setIcon(const QString& icon) {
    m_icon = icon;
    showLocomotivePicture();
}

// The picture the station or the layout has for this locomotive, else the placeholder; its name beside.
void LocomotiveForm::showLocomotivePicture() {
    const qreal ratio = devicePixelRatioF();
    m_picture->setPixmap(m_pictures ? m_pictures->picture(m_icon, LocomotivePictureBox, ratio)
                                    : LocomotivePictureBook::placeholder(LocomotivePictureBox, ratio));
    const QString about = m_pictures ? m_pictures->describe(m_icon) : QString();
    m_picture->setToolTip(about);
    m_pictureName->setText(m_icon.isEmpty() ? tr("none") : m_icon);
    m_pictureName->setToolTip(about);
}

void LocomotiveForm::buildFunctionRows() {
    m_functions->setSelectionMode(QAbstractItemView::NoSelection);
    m_functions->setFocusPolicy(Qt::NoFocus);
    m_functions->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_functions->horizontalHeader()->setSectionResizeMode(PictureColumn, QHeaderView::Stretch);
    m_functions->setIconSize(QSize(PictureSize, PictureSize));
    m_functions->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    for (int row = 0; row < m_functions->rowCount(); ++row) {
        m_functions->setVerticalHeaderItem(row, new QTableWidgetItem(QStringLiteral("F%1").arg(row)));
        auto* icon = new QSpinBox(m_functions);
        icon->setRange(0, cs2config::LocomotiveEditor::MaxIcon);
        auto* trigger = new QComboBox(m_functions);
        for (const FunctionTrigger kind : Triggers)
            trigger->addItem(QString(), int(kind));
        auto* duration = new QSpinBox(m_functions);
        duration->setRange(0, cs2config::LocomotiveEditor::MaxDuration);
        m_functions->setCellWidget(row, IconColumn, icon);
        auto* picture = new QTableWidgetItem;
        picture->setFlags(Qt::ItemIsEnabled);
        m_functions->setItem(row, PictureColumn, picture);
        m_functions->setCellWidget(row, TriggerColumn, trigger);
        m_functions->setCellWidget(row, DurationColumn, duration);
        connect(icon, &QSpinBox::valueChanged, this, [this, row] {
            showPicture(row);
            emit edited();
        });
        connect(duration, &QSpinBox::valueChanged, this, &LocomotiveForm::edited);
        connect(trigger, &QComboBox::currentIndexChanged, this, [this, row] {
            updateDuration(row);
            emit edited();
        });
        updateDuration(row);
    }
}

// What the icon number shows: our drawing of its kind and the kind's name ("Horn"), or just the number's
// name ("Function") where we have no drawing for it.
void LocomotiveForm::showPicture(int function) {
    QTableWidgetItem* picture = m_functions->item(function, PictureColumn);
    const FunctionKind kind = FunctionIcons::kindOf(iconBox(function)->value());
    picture->setIcon(FunctionIcons::icon(kind, palette().color(QPalette::Text), PictureSize * 2));
    picture->setText(FunctionIcons::name(kind));
}

QString LocomotiveForm::pictureText(int function) const {
    return m_functions->item(function, PictureColumn)->text();
}

bool LocomotiveForm::showsPicture(int function) const {
    return !m_functions->item(function, PictureColumn)->icon().isNull();
}

QSpinBox* LocomotiveForm::iconBox(int function) const {
    return qobject_cast<QSpinBox*>(m_functions->cellWidget(function, IconColumn));
}

QComboBox* LocomotiveForm::triggerBox(int function) const {
    return qobject_cast<QComboBox*>(m_functions->cellWidget(function, TriggerColumn));
}

QSpinBox* LocomotiveForm::durationBox(int function) const {
    return qobject_cast<QSpinBox*>(m_functions->cellWidget(function, DurationColumn));
}

// The time only means something for a timed key; a new timed key starts at 1.
void LocomotiveForm::updateDuration(int function) {
    const bool timed = triggerBox(function)->currentData().toInt() == int(FunctionTrigger::Timed);
    QSpinBox* duration = durationBox(function);
    duration->setEnabled(timed);
    if (timed && duration->value() == 0)
        duration->setValue(1);
}

void LocomotiveForm::setSettings(const cs2config::LocomotiveSettings& settings) {
    const QSignalBlocker blockName(m_name), blockDecoder(m_decoder), blockAddress(m_address);
    m_name->setText(QString::fromStdString(settings.name));
    m_decoder->setCurrentIndex(m_decoder->findData(int(settings.decoder)));
    m_address->setValue(int(settings.address));
    for (int row = 0; row < m_functions->rowCount(); ++row) {
        cs2config::FunctionSetting function{row, 0, FunctionTrigger::Latching, 0};
        for (const cs2config::FunctionSetting& given : settings.functions)
            if (given.number == row)
                function = given;
        const QSignalBlocker blockIcon(iconBox(row)), blockTrigger(triggerBox(row)),
            blockDuration(durationBox(row));
        iconBox(row)->setValue(function.icon);
        const int trigger = triggerBox(row)->findData(int(function.trigger));
        triggerBox(row)->setCurrentIndex(trigger < 0 ? 0 : trigger);
        durationBox(row)->setValue(function.duration);
        updateDuration(row);
        showPicture(row);
    }
    showAddressRange();
}

cs2config::LocomotiveSettings LocomotiveForm::settings() const {
    cs2config::LocomotiveSettings settings;
    settings.name = m_name->text().toStdString();
    settings.decoder = m_decoder->currentIndex() < 0 ? LocomotiveDecoder::None
                                                     : LocomotiveDecoder(m_decoder->currentData().toInt());
    settings.address = std::uint32_t(m_address->value());
    for (int row = 0; row < m_functions->rowCount(); ++row) {
        const auto trigger = FunctionTrigger(triggerBox(row)->currentData().toInt());
        settings.functions.push_back({row, iconBox(row)->value(), trigger,
                                      trigger == FunctionTrigger::Timed ? durationBox(row)->value() : 0});
    }
    return settings;
}

void LocomotiveForm::showAddressRange() {
    const auto range = cs2config::addressRange(LocomotiveDecoder(m_decoder->currentData().toInt()));
    m_addressRange->setText(range ? tr("allowed: %1–%2").arg(range->minimum).arg(range->maximum) : QString());
}

void LocomotiveForm::retranslate() {
    m_nameLabel->setText(tr("Name:"));
    m_decoderLabel->setText(tr("Decoder:"));
    m_addressLabel->setText(tr("Address:"));
    showLocomotivePicture();
    for (int i = 0; i < m_decoder->count(); ++i)
        m_decoder->setItemText(
            i, LocomotiveFileModel::decoderText(LocomotiveDecoder(m_decoder->itemData(i).toInt())));
    m_functions->setHorizontalHeaderLabels({tr("Icon"), tr("Shows"), tr("Trigger"), tr("Time")});
    for (int row = 0; row < m_functions->rowCount(); ++row) {
        showPicture(row);
        QComboBox* trigger = triggerBox(row);
        trigger->setItemText(0, tr("latching"));
        trigger->setItemText(1, tr("momentary"));
        trigger->setItemText(2, tr("timed"));
        trigger->setItemText(3, tr("as in the file"));
        iconBox(row)->setSpecialValueText(tr("none"));
        durationBox(row)->setSpecialValueText(QStringLiteral("–"));
    }
    showAddressRange();
}

} // namespace stellwerk::ui
