#include "throttle/ThrottleWidget.h"

#include "common/Contrast.h"
#include "common/LocomotivePictureBook.h"
#include "common/LocomotiveTableModel.h"
#include "common/NotReported.h"
#include "throttle/FunctionPad.h"
#include "throttle/SpeedScale.h"
#include "throttle/StyleSheetSupport.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

namespace stellwerk::ui {
namespace {

constexpr int SpeedUnitsPerPercent = model::Locomotive::MaxSpeed / 100;
// A dragged slider sends at most one speed command per this many milliseconds.
constexpr int SendIntervalMs = 40;
// The locomotive's picture in the header, 3:1 like the stations' pictures.
constexpr QSize PictureBox(132, 44);

const char* const UnacknowledgedProperty = "unacknowledged";
const char* const RequestedProperty = "requested";

// Stop loco is outlined in a red that reads on the button's colour: a stop, but for this locomotive only,
// never the layout's solid red STOP.
QColor stopLocoColour(const QPalette& palette) {
    const QColor button = palette.color(QPalette::Active, QPalette::Button);
    const QColor red = button.lightness() > 127 ? QColor(0xa3, 0x15, 0x15) : QColor(0xff, 0x8a, 0x80);
    return Contrast::ratio(red, button) >= Contrast::ForText
               ? red
               : palette.color(QPalette::Active, QPalette::ButtonText);
}

// Greyed (not reported, no locomotive) texts stay readable: the style's disabled grey is too pale.
QString greyedStyle(const QPalette& palette) {
    const auto greyed = [&palette](QPalette::ColorRole text, QPalette::ColorRole background) {
        return Contrast::faded(palette.color(QPalette::Active, text),
                               palette.color(QPalette::Active, background), Contrast::ForText)
            .name();
    };
    return QStringLiteral("QPushButton:disabled { color: %1; }"
                          "QLabel:disabled { color: %2; }")
        .arg(greyed(QPalette::ButtonText, QPalette::Button), greyed(QPalette::WindowText, QPalette::Window));
}

QString throttleStyle(const QPalette& palette) {
    const QColor button = palette.color(QPalette::Active, QPalette::Button);
    return greyedStyle(palette) +
           QStringLiteral(
               "QFrame#speedFrame { border: 2px solid transparent; border-radius: 4px; }"
               "QFrame#speedFrame[requested=\"true\"] { border: 2px dashed palette(highlight); }"
               "QFrame#speedFrame[unacknowledged=\"true\"] { border: 2px solid %1; }"
               "QLabel#speedRequest { font-style: italic; }"
               "QPushButton[unacknowledged=\"true\"] { border: 2px solid %1; border-radius: 4px; padding: "
               "5px; }"
               "QPushButton#emergencyStop { background: palette(button); color: %2; border: 2px solid %2;"
               " font-weight: bold; border-radius: 4px; padding: 5px; }"
               "QPushButton#emergencyStop:pressed { background: %2; color: palette(button); }"
               "QPushButton#emergencyStop:disabled { color: %3; border-color: %3; }"
               "QPushButton#emergencyStop[unacknowledged=\"true\"] { border: 3px solid %1; }")
               .arg(QLatin1String(WarningOutline), stopLocoColour(palette).name(),
                    Contrast::faded(palette.color(QPalette::ButtonText), button, Contrast::ForText).name());
}

int digitOf(const QKeyEvent* event) {
    const int key = event->key();
    return key >= Qt::Key_0 && key <= Qt::Key_9 ? key - Qt::Key_0 : -1;
}

} // namespace

ThrottleWidget::ThrottleWidget(QWidget* parent) : QFrame(parent), m_sendTimer(new QTimer(this)) {
    setObjectName(QStringLiteral("throttle"));
    setFrameShape(QFrame::StyledPanel);
    setFocusPolicy(Qt::StrongFocus);
    setStyleSheet(throttleStyle(palette()));
    m_sendTimer->setSingleShot(true);
    m_sendTimer->setInterval(SendIntervalMs);
    connect(m_sendTimer, &QTimer::timeout, this, &ThrottleWidget::sendSpeed);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(createHeader());
    layout->addWidget(createSpeedArea(), 1);
    m_direction = new QPushButton(this);
    m_direction->setObjectName(QStringLiteral("direction"));
    m_direction->setFocusPolicy(Qt::NoFocus);
    connect(m_direction, &QPushButton::clicked, this, &ThrottleWidget::reverseDirection);
    m_stop = new QPushButton(this);
    m_stop->setObjectName(QStringLiteral("emergencyStop"));
    m_stop->setFocusPolicy(Qt::NoFocus);
    connect(m_stop, &QPushButton::clicked, this, &ThrottleWidget::emergencyStop);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_direction, 1);
    buttons->addWidget(m_stop, 1);
    layout->addLayout(buttons);
    m_functions = new FunctionPad(this);
    layout->addWidget(m_functions);
    setFocusProxy(m_slider);
    retranslate();
    showLocomotive();
}

QWidget* ThrottleWidget::createHeader() {
    auto* header = new QWidget(this);
    auto* layout = new QGridLayout(header);
    layout->setContentsMargins(0, 0, 0, 0);
    m_numberLabel = new QLabel(header);
    m_numberLabel->setObjectName(QStringLiteral("throttleNumber"));
    m_choice = new QComboBox(header);
    m_choice->setObjectName(QStringLiteral("locomotiveChoice"));
    m_choice->setFocusPolicy(Qt::ClickFocus);
    m_choice->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_choice->setMinimumContentsLength(20);
    connect(m_choice, &QComboBox::activated, this, &ThrottleWidget::choose);
    m_close = new QToolButton(header);
    m_close->setObjectName(QStringLiteral("closeThrottle"));
    m_close->setFocusPolicy(Qt::NoFocus);
    m_close->setAutoRaise(true);
    m_close->setText(QStringLiteral("✕"));
    connect(m_close, &QToolButton::clicked, this, &ThrottleWidget::closeRequested);
    m_details = new QLabel(header);
    m_details->setObjectName(QStringLiteral("locomotiveDetails"));
    m_details->setEnabled(false);
    m_picture = new QLabel(header);
    m_picture->setObjectName(QStringLiteral("locomotivePicture"));
    m_picture->setFixedSize(PictureBox);
    m_picture->setAlignment(Qt::AlignCenter);
    auto* about = new QHBoxLayout;
    about->addWidget(m_picture);
    about->addWidget(m_details, 1);
    layout->addWidget(m_numberLabel, 0, 0);
    layout->addWidget(m_choice, 0, 1);
    layout->addWidget(m_close, 0, 2);
    layout->addLayout(about, 1, 1, 1, 2);
    layout->setColumnStretch(1, 1);
    return header;
}

QWidget* ThrottleWidget::createSpeedArea() {
    m_speedFrame = new QFrame(this);
    m_speedFrame->setObjectName(QStringLiteral("speedFrame"));
    auto* layout = new QGridLayout(m_speedFrame);
    m_slider = new QSlider(Qt::Vertical, m_speedFrame);
    m_slider->setObjectName(QStringLiteral("speed"));
    m_slider->setRange(0, 100);
    m_slider->setSingleStep(SpeedStepPercent);
    m_slider->setPageStep(SpeedPageStepPercent);
    m_slider->setMinimumHeight(160);
    connect(m_slider, &QSlider::valueChanged, this, &ThrottleWidget::sliderMoved);
    connect(m_slider, &QSlider::sliderReleased, this, &ThrottleWidget::showState);
    m_scale = new SpeedScale(m_speedFrame);
    m_speedText = new QLabel(m_speedFrame);
    m_speedText->setObjectName(QStringLiteral("speedText"));
    m_speedText->setAlignment(Qt::AlignCenter);
    QFont big = m_speedText->font();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    big.setBold(true);
    m_speedText->setFont(big);
    m_requestText = new QLabel(m_speedFrame);
    m_requestText->setObjectName(QStringLiteral("speedRequest"));
    m_requestText->setAlignment(Qt::AlignCenter);
    QSizePolicy keepRoom = m_requestText->sizePolicy();
    keepRoom.setRetainSizeWhenHidden(true); // nothing below moves when a request comes and goes
    m_requestText->setSizePolicy(keepRoom);
    m_requestText->hide();
    layout->addWidget(m_speedText, 0, 0, 1, 3);
    layout->addWidget(m_requestText, 1, 0, 1, 3);
    layout->addWidget(m_slider, 2, 1, Qt::AlignHCenter);
    layout->addWidget(m_scale, 2, 2);
    layout->setColumnStretch(0, 1);
    layout->setColumnStretch(3, 1);
    return m_speedFrame;
}

void ThrottleWidget::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    m_speedInFlight = 0; // a railway that goes reports none of its commands any more
    // The marks stay: a new session does not make the failed command carried out.
    if (m_railway) {
        using model::Railway;
        connect(m_railway, &Railway::loaded, this, &ThrottleWidget::showLocomotive);
        connect(m_railway, &Railway::stateReportedChanged, this, &ThrottleWidget::showLocomotive);
        connect(m_railway, &Railway::locomotivesChanged, this, &ThrottleWidget::locomotivesChanged);
        connect(m_railway, &Railway::locomotiveCommandSent, this, &ThrottleWidget::commandSent);
        connect(m_railway, &Railway::locomotiveCommandAcknowledged, this,
                &ThrottleWidget::commandAcknowledged);
        connect(m_railway, &Railway::locomotiveCommandFailed, this, &ThrottleWidget::commandFailed);
        connect(m_railway, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    showLocomotive();
}

void ThrottleWidget::setLocomotive(std::uint32_t loco) {
    if (loco == m_loco)
        return;
    m_loco = loco;
    m_speedInFlight = 0;
    m_wantedSpeed = -1;
    m_sendTimer->stop();
    m_marks.clear();
    showLocomotive();
    emit locomotiveChosen(loco);
}

void ThrottleWidget::setNumber(int number) {
    m_number = number;
    retranslate();
}

void ThrottleWidget::fillChoice() {
    const QSignalBlocker blocker(m_choice);
    m_choice->clear();
    m_choice->addItem(tr("Choose a locomotive…"), 0U);
    if (m_railway)
        for (const model::Locomotive& loco : m_railway->state().locomotives().items())
            m_choice->addItem(
                QStringLiteral("%1 (%2)").arg(loco.displayName(), LocomotiveTableModel::addressText(loco)),
                loco.id().value());
    const int index = m_choice->findData(m_loco);
    if (index < 0 && m_loco != 0) { // remembered, but not (yet) on this station
        const bool loaded = m_railway && !m_railway->state().locomotives().items().empty();
        m_choice->addItem(loaded ? tr("Locomotive 0x%1 (not on this station)").arg(m_loco, 0, 16)
                                 : tr("Locomotive 0x%1 (waiting for the station)").arg(m_loco, 0, 16),
                          m_loco);
    }
    m_choice->setCurrentIndex(std::max(m_choice->findData(m_loco), 0));
}

void ThrottleWidget::choose(int index) {
    const std::uint32_t wanted = m_choice->itemData(index).toUInt();
    if (wanted != m_loco && !confirmChange(wanted)) {
        const QSignalBlocker blocker(m_choice);
        m_choice->setCurrentIndex(std::max(m_choice->findData(m_loco), 0));
    } else {
        setLocomotive(wanted);
    }
    setFocus(); // back to the slider: keys drive, and Space stays the window's STOP
}

// A running locomotive would run on with nobody at its throttle: the user says so first.
bool ThrottleWidget::confirmChange(std::uint32_t wanted) {
    const model::Locomotive* running = driven();
    if (!running || running->speed() == 0)
        return true;
    const model::Locomotive* next = m_railway->locomotive(wanted);
    const QString nextName = next ? next->displayName() : tr("no locomotive");
    QMessageBox box(QMessageBox::Question, tr("Change locomotive"),
                    tr("%1 is running (%2). Drive %3 with this throttle instead?")
                        .arg(running->displayName(), speedWords(running->speed()), nextName),
                    QMessageBox::NoButton, this);
    box.setObjectName(QStringLiteral("changeLocomotiveQuestion"));
    box.setInformativeText(
        tr("%1 keeps running at its speed; this throttle no longer drives it.").arg(running->displayName()));
    QPushButton* change = box.addButton(tr("Drive %1").arg(nextName), QMessageBox::AcceptRole);
    QPushButton* keep = box.addButton(tr("Keep %1").arg(running->displayName()), QMessageBox::RejectRole);
    box.setDefaultButton(keep);
    box.setEscapeButton(keep);
    box.exec();
    return box.clickedButton() == change;
}

void ThrottleWidget::setPictures(LocomotivePictureBook* pictures) {
    if (m_pictures)
        m_pictures->disconnect(this);
    m_pictures = pictures;
    if (m_pictures)
        connect(m_pictures, &LocomotivePictureBook::changed, this, &ThrottleWidget::showPicture);
    showPicture();
}

void ThrottleWidget::showPicture() {
    const model::Locomotive* loco = m_railway && m_loco ? m_railway->locomotive(m_loco) : nullptr;
    m_picture->setVisible(loco != nullptr);
    if (!loco)
        return;
    const QString icon = loco->iconName();
    m_picture->setPixmap(m_pictures ? m_pictures->picture(icon, PictureBox, devicePixelRatioF())
                                    : LocomotivePictureBook::placeholder(PictureBox, devicePixelRatioF()));
    m_picture->setToolTip(m_pictures ? m_pictures->describe(icon) : QString());
    m_picture->setProperty("placeholder", !m_pictures || !m_pictures->hasPicture(icon));
}

void ThrottleWidget::showLocomotive() {
    fillChoice();
    showPicture();
    m_functions->setLocomotive(m_railway, m_loco);
    const model::Locomotive* loco = m_railway && m_loco ? m_railway->locomotive(m_loco) : nullptr;
    m_scale->setTachoMax(loco ? loco->tachoMax() : 0);
    // While not reported, nothing shown here is vouched for: speed, direction and functions are greyed;
    // the emergency stop stays usable.
    const bool reported = loco && m_railway->isStateReported();
    m_slider->setEnabled(reported);
    m_direction->setEnabled(reported);
    m_functions->setEnabled(reported);
    m_speedText->setEnabled(reported);
    m_stop->setEnabled(loco != nullptr);
    // The marks stay: the model going silent or loading again does not carry out a failed command.
    retranslate();
    showState();
}

void ThrottleWidget::locomotivesChanged(const QList<quint32>& ids) {
    bool unknown = false;
    for (const quint32 id : ids)
        unknown = unknown || m_choice->findData(id) < 0;
    if (unknown)
        fillChoice(); // a locomotive another controller drives appeared on the bus
    if (ids.contains(m_loco)) {
        if (m_functions->isEmpty() && m_railway->locomotive(m_loco))
            showLocomotive();
        showState();
    }
}

// Shows the confirmed speed, direction and functions; the slider only while nobody moves it.
void ThrottleWidget::showState() {
    const model::Locomotive* loco = m_railway && m_loco ? m_railway->locomotive(m_loco) : nullptr;
    const bool userMoving = m_slider->isSliderDown() || m_sendTimer->isActive() || m_speedInFlight > 0;
    if (!userMoving) {
        const QSignalBlocker blocker(m_slider);
        m_slider->setValue(loco ? (loco->speed() + SpeedUnitsPerPercent / 2) / SpeedUnitsPerPercent : 0);
    }
    m_functions->refresh();
    retranslate();
}

// Only the user moves the slider (the throttle sets it with its signals blocked).
void ThrottleWidget::sliderMoved(int percent) {
    clearMark(Control::Speed); // a new request: what failed before is no longer what the user asks
    m_wantedSpeed = percent * SpeedUnitsPerPercent;
    if (!m_sendTimer->isActive())
        m_sendTimer->start();
    retranslate(); // the request follows the slider
}

void ThrottleWidget::reverseDirection() {
    clearMark(Control::Direction);
    if (m_railway && m_loco != 0)
        m_railway->reverse(m_loco);
}

void ThrottleWidget::emergencyStop() {
    m_sendTimer->stop(); // a speed still waiting to be sent must not start the locomotive again
    m_wantedSpeed = -1;
    clearMark(Control::EmergencyStop);
    if (m_railway && m_loco != 0)
        m_railway->emergencyStop(m_loco);
}

void ThrottleWidget::sendSpeed() {
    if (m_railway && m_loco != 0 && m_wantedSpeed >= 0)
        m_railway->setSpeed(m_loco, m_wantedSpeed);
    m_wantedSpeed = -1;
}

void ThrottleWidget::commandSent(quint32 loco, Control control, int) {
    if (loco == m_loco && control == Control::Speed)
        ++m_speedInFlight;
}

void ThrottleWidget::commandAcknowledged(quint32 loco, Control control, int function) {
    if (loco != m_loco)
        return;
    if (control == Control::Function) {
        m_functions->clearMark(function);
        return;
    }
    if (control == Control::Speed)
        m_speedInFlight = std::max(m_speedInFlight - 1, 0);
    // The station carried out a command again: whatever failed before is history.
    for (const Control marked : {Control::Speed, Control::Direction, Control::EmergencyStop})
        if (marked == control || control == Control::EmergencyStop)
            clearMark(marked);
    showState();
}

void ThrottleWidget::commandFailed(quint32 loco, Control control, int function, const QString& reason) {
    if (loco != m_loco)
        return;
    if (control == Control::Function) {
        m_functions->markUnacknowledged(function, reason);
        m_functions->refresh();
        return;
    }
    if (control == Control::Speed)
        m_speedInFlight = std::max(m_speedInFlight - 1, 0);
    setMark(control, reason);
    showState(); // back to what the station last confirmed
}

QWidget* ThrottleWidget::markedWidget(Control control) const {
    switch (control) {
    case Control::Speed:
        return m_speedFrame;
    case Control::Direction:
        return m_direction;
    case Control::EmergencyStop:
        return m_stop;
    case Control::Function:
        break;
    }
    return nullptr;
}

void ThrottleWidget::setMark(Control control, const QString& reason) {
    QWidget* widget = markedWidget(control);
    if (!widget)
        return;
    m_marks[control] = reason;
    widget->setProperty(UnacknowledgedProperty, true);
    repolish(widget);
    retranslate();
}

void ThrottleWidget::clearMark(Control control) {
    QWidget* widget = markedWidget(control);
    if (!widget || m_marks.erase(control) == 0)
        return;
    widget->setProperty(UnacknowledgedProperty, false);
    repolish(widget);
    retranslate();
}

bool ThrottleWidget::isUnacknowledged(Control control, int function) const {
    return control == Control::Function ? m_functions->isMarked(function) : m_marks.contains(control);
}

QString ThrottleWidget::speedText() const {
    return m_speedText->text();
}

QString ThrottleWidget::requestText() const {
    return m_requestText->isHidden() ? QString() : m_requestText->text();
}

const model::Locomotive* ThrottleWidget::driven() const {
    return m_railway && m_loco != 0 ? m_railway->locomotive(m_loco) : nullptr;
}

// `speed` (0..1000) as the locomotive's speedometer shows it, or in percent without one.
QString ThrottleWidget::speedWords(int speed) const {
    const model::Locomotive* loco = driven();
    if (!loco)
        return tr("—");
    const int max = model::Locomotive::MaxSpeed;
    return loco->tachoMax() > 0 ? tr("%1 km/h").arg((speed * loco->tachoMax() + max / 2) / max)
                                : tr("%1 %").arg((speed + SpeedUnitsPerPercent / 2) / SpeedUnitsPerPercent);
}

bool ThrottleWidget::handlesKey(const QKeyEvent* event) const {
    if (event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    switch (event->key()) {
    case Qt::Key_Up:
    case Qt::Key_Down:
    case Qt::Key_PageUp:
    case Qt::Key_PageDown:
    case Qt::Key_Plus:
    case Qt::Key_Minus:
    case Qt::Key_R:
    case Qt::Key_E:
        return true;
    default:
        return digitOf(event) >= 0; // never Space or Escape: the window's STOP keys
    }
}

bool ThrottleWidget::event(QEvent* event) {
    // Keep our keys from window shortcuts while a throttle has focus.
    if (event->type() == QEvent::ShortcutOverride && handlesKey(static_cast<QKeyEvent*>(event))) {
        event->accept();
        return true;
    }
    return QFrame::event(event);
}

void ThrottleWidget::keyPressEvent(QKeyEvent* event) {
    if (!handlesKey(event) || !m_railway || m_loco == 0) {
        QFrame::keyPressEvent(event);
        return;
    }
    drive(event);
    event->accept(); // also when greyed: the key is the throttle's, not the window's
}

// A key acts on its control only while that control can be used (not while the state is not reported,
// except the emergency stop). False when it did nothing.
bool ThrottleWidget::drive(const QKeyEvent* event) {
    const bool speed = m_slider->isEnabled();
    switch (event->key()) {
    case Qt::Key_Up:
    case Qt::Key_Plus:
        return speed && (m_slider->triggerAction(QSlider::SliderSingleStepAdd), true);
    case Qt::Key_Down:
    case Qt::Key_Minus:
        return speed && (m_slider->triggerAction(QSlider::SliderSingleStepSub), true);
    case Qt::Key_PageUp:
        return speed && (m_slider->triggerAction(QSlider::SliderPageStepAdd), true);
    case Qt::Key_PageDown:
        return speed && (m_slider->triggerAction(QSlider::SliderPageStepSub), true);
    case Qt::Key_R:
        return m_direction->isEnabled() && !event->isAutoRepeat() && (reverseDirection(), true);
    case Qt::Key_E:
        emergencyStop();
        return true;
    default:
        return m_functions->isEnabled() && !event->isAutoRepeat() &&
               (m_functions->press(digitOf(event)), true);
    }
}

void ThrottleWidget::keyReleaseEvent(QKeyEvent* event) {
    if (const int digit = digitOf(event); digit >= 0 && !event->isAutoRepeat() && handlesKey(event)) {
        if (m_functions->isEnabled())
            m_functions->release(digit);
        event->accept();
        return;
    }
    QFrame::keyReleaseEvent(event);
}

void ThrottleWidget::retranslate() {
    m_numberLabel->setText(m_number > 0 ? QString::number(m_number) : QString());
    m_numberLabel->setToolTip(m_number > 0 ? tr("Alt+%1 puts the keyboard on this throttle").arg(m_number)
                                           : QString());
    m_close->setToolTip(tr("Close this throttle"));
    if (m_choice->count() > 0 && m_choice->itemData(0).toUInt() == 0)
        m_choice->setItemText(0, tr("Choose a locomotive…"));
    const model::Locomotive* loco = driven();
    m_details->setText(loco ? LocomotiveTableModel::addressText(*loco) : QString());
    if (loco && m_pictures)
        m_picture->setToolTip(m_pictures->describe(loco->iconName()));
    const bool backward = loco && loco->direction() == cs2::Direction::Backward;
    m_direction->setText(backward ? tr("◀ Backward") : tr("Forward ▶"));
    m_direction->setToolTip(tr("Change direction (R); the station stops the locomotive first"));
    m_stop->setText(tr("Stop loco"));
    m_stop->setToolTip(tr("Emergency stop for this locomotive only (E); STOP in the toolbar stops the "
                          "whole layout"));
    retranslateSpeed();
    if (NotReported::applies(m_railway))
        for (QWidget* greyed : {static_cast<QWidget*>(m_slider), static_cast<QWidget*>(m_direction)})
            greyed->setToolTip(NotReported::reason());
    retranslateMarks();
}

// The big number is the confirmed speed; the slider's own value, while the station has not confirmed it,
// is the request below it.
void ThrottleWidget::retranslateSpeed() {
    const model::Locomotive* loco = driven();
    const int percent = m_slider->value();
    m_speedText->setText(speedWords(loco ? loco->speed() : 0));
    m_speedText->setToolTip(NotReported::applies(m_railway) ? NotReported::reason()
                                                            : tr("The speed the station confirmed"));
    const int confirmed = loco ? (loco->speed() + SpeedUnitsPerPercent / 2) / SpeedUnitsPerPercent : 0;
    const bool requested = loco && percent != confirmed;
    m_requestText->setText(tr("Requested: %1").arg(speedWords(percent * SpeedUnitsPerPercent)));
    m_requestText->setToolTip(tr("Sent to the station; the number above changes when it confirms"));
    m_requestText->setVisible(requested);
    if (m_speedFrame->property(RequestedProperty).toBool() != requested) {
        m_speedFrame->setProperty(RequestedProperty, requested);
        repolish(m_speedFrame);
    }
    m_slider->setToolTip(tr("Speed: %1 % (Up/Down, +/-, PageUp/PageDown)").arg(percent));
}

void ThrottleWidget::retranslateMarks() {
    m_speedFrame->setToolTip(QString()); // the buttons got their own tooltips again above
    for (const auto& [control, reason] : m_marks) {
        const QString tip = tr("The station did not acknowledge the last command: %1").arg(reason);
        markedWidget(control)->setToolTip(tip);
        if (control == Control::Speed)
            m_slider->setToolTip(tip);
    }
}

void ThrottleWidget::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    else if (event->type() == QEvent::PaletteChange)
        restyle(this, throttleStyle(palette())); // palette(...) in a style sheet is resolved when it is set
    QFrame::changeEvent(event);
}

} // namespace stellwerk::ui
