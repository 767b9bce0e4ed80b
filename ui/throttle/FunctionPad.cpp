#include "throttle/FunctionPad.h"

#include "common/Contrast.h"
#include "common/FunctionIcons.h"
#include "model/Railway.h"
#include "throttle/StyleSheetSupport.h"

#include <QEvent>
#include <QGridLayout>
#include <QTimer>
#include <QToolButton>
#include <algorithm>

namespace stellwerk::ui {
namespace {

constexpr int IconSize = 24;
constexpr int MillisecondsPerTimedUnit = 1000; // `..dauer` read as seconds (the document names no unit)

const char* const UnacknowledgedProperty = "unacknowledged";

// How far a greyed "on" key keeps the highlight: visibly on, yet paler than a usable one.
constexpr double GreyedHighlight = 0.35;

QString padStyle(const QPalette& palette) {
    const FunctionPad::Greyed greyed = FunctionPad::greyed(palette);
    return QStringLiteral(
               "QToolButton { border: 1px solid palette(mid); border-radius: 4px; padding: 2px;"
               " background: palette(button); min-width: 44px; min-height: 44px; }"
               "QToolButton:checked { background: palette(highlight); color: palette(highlighted-text);"
               " border-color: palette(highlight); }"
               // greyed while the station's state is not reported: "on" is then only what it last said
               "QToolButton:disabled { background: %2; color: %3; }"
               "QToolButton:checked:disabled { background: %4; color: %5; border-color: %4; }"
               "QToolButton[unacknowledged=\"true\"] { border: 2px solid %1; }")
        .arg(QLatin1String(WarningOutline), greyed.offBackground.name(), greyed.offText.name(),
             greyed.onBackground.name(), greyed.onText.name());
}

} // namespace

FunctionPad::Greyed FunctionPad::greyed(const QPalette& palette) {
    const QColor button = palette.color(QPalette::Active, QPalette::Button);
    const QColor on =
        Contrast::mix(palette.color(QPalette::Active, QPalette::Highlight), button, GreyedHighlight);
    const QColor text = palette.color(QPalette::Active, QPalette::ButtonText);
    const QColor onText = palette.color(QPalette::Active, QPalette::HighlightedText);
    // On the pale highlight, whichever of the two text colours reads better is faded.
    const QColor onBase = Contrast::ratio(text, on) >= Contrast::ratio(onText, on) ? text : onText;
    return {Contrast::faded(text, button, Contrast::ForText), button,
            Contrast::faded(onBase, on, Contrast::ForText), on};
}

FunctionPad::FunctionPad(QWidget* parent) : QWidget(parent), m_grid(new QGridLayout(this)) {
    setObjectName(QStringLiteral("functionPad"));
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setSpacing(4);
    setStyleSheet(padStyle(palette()));
}

void FunctionPad::setLocomotive(model::Railway* railway, std::uint32_t loco) {
    clear();
    if (loco != m_loco)
        m_marks.clear(); // the same locomotive again (its state reported anew): the marks stay
    m_railway = railway;
    m_loco = loco;
    const model::Locomotive* found = locomotive();
    if (!found)
        return;
    for (const model::LocomotiveFunction& function : found->functions())
        if (function.icon != 0 || function.on)
            addKey(function);
    if (m_keys.empty())
        for (int number = 0; number < DefaultKeys; ++number)
            addKey({number, 0, cs2config::FunctionTrigger::Latching, found->functionOn(number), 0});
    retranslate(); // icons first: they decide the keys' height
    reserveRows();
}

// Every pad is at least DefaultKeys high, so that throttles side by side keep their sliders level.
void FunctionPad::reserveRows() {
    int height = 0;
    for (const auto& [number, key] : m_keys)
        height = std::max(height, key.button->sizeHint().height());
    const int keys = std::max(int(m_keys.size()), DefaultKeys);
    const int rows = (keys + Columns - 1) / Columns;
    setFixedHeight(rows * height + (rows - 1) * m_grid->verticalSpacing());
    m_grid->setAlignment(Qt::AlignTop);
}

const model::Locomotive* FunctionPad::locomotive() const {
    return m_railway && m_loco != 0 ? m_railway->locomotive(m_loco) : nullptr;
}

void FunctionPad::clear() {
    for (auto& [number, key] : m_keys)
        delete key.button;
    m_keys.clear();
}

void FunctionPad::addKey(const model::LocomotiveFunction& function) {
    auto* button = new QToolButton(this);
    button->setObjectName(QStringLiteral("function%1").arg(function.number));
    button->setCheckable(true);
    button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    button->setFocusPolicy(Qt::NoFocus); // Space stays the layout's STOP key
    button->setText(QStringLiteral("F%1").arg(function.number));
    const int index = int(m_keys.size());
    m_grid->addWidget(button, index / Columns, index % Columns);
    const int number = function.number;
    connect(button, &QToolButton::pressed, this, [this, number] { press(number); });
    connect(button, &QToolButton::released, this, [this, number] { release(number); });
    // A click must not change what the button shows: only the station's confirmation does.
    connect(button, &QToolButton::clicked, this, [this, number] {
        if (auto it = m_keys.find(number); it != m_keys.end())
            updateKey(it->second);
    });
    button->setProperty(UnacknowledgedProperty, m_marks.contains(number));
    Key& key = m_keys[number];
    key.button = button;
    key.function = function;
    updateKey(key);
}

QToolButton* FunctionPad::button(int function) const {
    const auto it = m_keys.find(function);
    return it == m_keys.end() ? nullptr : it->second.button;
}

void FunctionPad::refresh() {
    for (auto& [number, key] : m_keys)
        updateKey(key);
}

void FunctionPad::updateKey(Key& key) {
    const model::Locomotive* loco = locomotive();
    key.button->setChecked(loco && loco->functionOn(key.function.number));
}

void FunctionPad::press(int function) {
    const model::Locomotive* loco = locomotive();
    if (!loco || function < 0 || function >= model::Locomotive::MaxFunctions)
        return;
    clearMark(function); // asked again: what failed before is no longer what the user asks
    const model::LocomotiveFunction* known = loco->function(function);
    const auto trigger = known ? known->trigger : cs2config::FunctionTrigger::Latching;
    switch (trigger) {
    case cs2config::FunctionTrigger::Momentary:
        m_railway->setFunction(m_loco, function, true);
        break;
    case cs2config::FunctionTrigger::Timed: {
        m_railway->setFunction(m_loco, function, true);
        QTimer::singleShot(known->duration * MillisecondsPerTimedUnit, this,
                           [railway = m_railway, loco = m_loco, function] {
                               if (railway)
                                   railway->setFunction(loco, function, false);
                           });
        break;
    }
    case cs2config::FunctionTrigger::Latching:
    case cs2config::FunctionTrigger::Unknown:
        m_railway->toggleFunction(m_loco, function);
        break;
    }
}

void FunctionPad::release(int function) {
    const model::Locomotive* loco = locomotive();
    const model::LocomotiveFunction* known = loco ? loco->function(function) : nullptr;
    if (known && known->trigger == cs2config::FunctionTrigger::Momentary)
        m_railway->setFunction(m_loco, function, false);
}

void FunctionPad::markUnacknowledged(int function, const QString& reason) {
    m_marks[function] = reason;
    if (QToolButton* key = button(function)) {
        key->setProperty(UnacknowledgedProperty, true);
        repolish(key);
    }
    retranslate();
}

void FunctionPad::clearMark(int function) {
    if (m_marks.erase(function) == 0)
        return;
    if (QToolButton* key = button(function)) {
        key->setProperty(UnacknowledgedProperty, false);
        repolish(key);
    }
    retranslate();
}

// The drawings in the keys' text colours, for usable and greyed keys alike. Always the Active colours: the
// pad's own palette() would hand out the disabled grey while the pad happens to be greyed (issue 32: such
// icons stayed pale until a language switch drew them again in black).
void FunctionPad::updateIcons() {
    const QPalette& colours = palette();
    const Greyed grey = greyed(colours);
    const QColor off = colours.color(QPalette::Active, QPalette::ButtonText);
    const QColor on = colours.color(QPalette::Active, QPalette::HighlightedText);
    for (auto& [number, key] : m_keys) {
        const FunctionKind kind = FunctionIcons::kindOf(key.function.icon);
        QIcon icon;
        if (kind != FunctionKind::Numbered) {
            const auto add = [&icon, kind](const QColor& colour, QIcon::Mode mode, QIcon::State state) {
                icon.addPixmap(FunctionIcons::icon(kind, colour, IconSize).pixmap(IconSize), mode, state);
            };
            add(off, QIcon::Normal, QIcon::Off);
            add(on, QIcon::Normal, QIcon::On);
            add(grey.offText, QIcon::Disabled, QIcon::Off);
            add(grey.onText, QIcon::Disabled, QIcon::On);
        }
        key.button->setIcon(icon);
        key.button->setIconSize(QSize(IconSize, IconSize));
        key.button->setToolButtonStyle(icon.isNull() ? Qt::ToolButtonTextOnly : Qt::ToolButtonTextUnderIcon);
    }
}

void FunctionPad::retranslate() {
    updateIcons();
    for (auto& [number, key] : m_keys) {
        const FunctionKind kind = FunctionIcons::kindOf(key.function.icon);
        QString how;
        switch (key.function.trigger) {
        case cs2config::FunctionTrigger::Momentary:
            how = tr("on while held");
            break;
        case cs2config::FunctionTrigger::Timed:
            how = tr("on for %n s", nullptr, key.function.duration);
            break;
        default:
            how = tr("on/off");
            break;
        }
        QString tip = tr("F%1: %2 (%3)").arg(number).arg(FunctionIcons::name(kind), how);
        if (const auto mark = m_marks.find(number); mark != m_marks.end())
            tip += QLatin1Char('\n') +
                   tr("The station did not acknowledge the last command: %1").arg(mark->second);
        key.button->setToolTip(tip);
    }
}

void FunctionPad::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    else if (event->type() == QEvent::PaletteChange) {
        restyle(this, padStyle(palette())); // palette(...) in a style sheet is resolved when it is set
        updateIcons();
    }
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
