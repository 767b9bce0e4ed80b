#include "throttle/ThrottlePanel.h"

#include "common/LayoutStateBanner.h"
#include "common/LocomotivePictureBook.h"
#include "common/ToolIcons.h"
#include "common/WrappingGrid.h"
#include "model/Railway.h"
#include "throttle/ThrottleSettings.h"
#include "throttle/ThrottleWidget.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QStyle>
#include <QVBoxLayout>
#include <algorithm>

namespace stellwerk::ui {
namespace {

// The picture on an offer to drive a locomotive.
constexpr QSize OfferPicture(54, 18);

} // namespace

ThrottlePanel::ThrottlePanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("throttlePanel"));
    auto* layout = new QVBoxLayout(this);
    auto* bar = new QHBoxLayout;
    m_add = new QPushButton(this);
    m_add->setObjectName(QStringLiteral("addThrottle"));
    m_add->setFocusPolicy(Qt::NoFocus);
    m_add->setIcon(ToolIcons::icon(ToolIcons::Tool::AddThrottle, palette().color(QPalette::ButtonText)));
    connect(m_add, &QPushButton::clicked, this, [this] {
        if (ThrottleWidget* throttle = addThrottle())
            throttle->locomotiveChoice()->setFocus();
    });
    m_keysHint = new QLabel(this);
    m_keysHint->setEnabled(false);
    m_keysHint->setWordWrap(true);
    bar->addWidget(m_add);
    bar->addWidget(m_keysHint, 1);
    layout->addLayout(bar);
    m_banner = new LayoutStateBanner(this);
    m_banner->setObjectName(QStringLiteral("throttleLayoutState"));
    layout->addWidget(m_banner);

    m_emptyText = new QLabel(this);
    m_emptyText->setObjectName(QStringLiteral("throttlesEmpty"));
    m_emptyText->setAlignment(Qt::AlignHCenter | Qt::AlignBottom); // just above the offers
    m_emptyText->setEnabled(false);
    m_emptyText->setWordWrap(true); // a narrow dock must not cut the sentence off
    layout->addWidget(m_emptyText, 1);
    m_offers = new QWidget(this);
    m_offers->setObjectName(QStringLiteral("driveOffers"));
    new QVBoxLayout(m_offers);
    layout->addWidget(m_offers);

    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_rack = new WrappingGrid(m_scroll);
    m_scroll->setWidget(m_rack);
    layout->addWidget(m_scroll, 1);
    layout->addStretch(0); // the room below the offers while no throttle is open

    createShortcuts();
    m_restoring = true;
    for (const std::uint32_t loco : ThrottleSettings::load())
        addThrottle(loco);
    m_restoring = false;
    retranslate();
    updateEmptyState();
}

void ThrottlePanel::createShortcuts() {
    for (int number = 1; number <= ThrottleSettings::MaximumThrottles; ++number) {
        auto* shortcut = new QShortcut(QKeySequence(Qt::ALT | Qt::Key(Qt::Key_0 + number)), this);
        connect(shortcut, &QShortcut::activated, this, [this, number] { focusThrottle(number); });
    }
}

void ThrottlePanel::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    if (m_railway) {
        connect(m_railway, &model::Railway::loaded, this, &ThrottlePanel::updateOffers);
        connect(m_railway, &model::Railway::locomotivesChanged, this, &ThrottlePanel::updateOffers);
    }
    m_banner->setRailway(railway);
    for (ThrottleWidget* throttle : m_throttles)
        throttle->setRailway(railway);
    updateEmptyState();
}

void ThrottlePanel::setPictures(LocomotivePictureBook* pictures) {
    if (m_pictures)
        m_pictures->disconnect(this);
    m_pictures = pictures;
    if (m_pictures)
        connect(m_pictures, &LocomotivePictureBook::changed, this, &ThrottlePanel::updateOffers);
    for (ThrottleWidget* throttle : m_throttles)
        throttle->setPictures(pictures);
    updateOffers();
}

ThrottleWidget* ThrottlePanel::addThrottle(std::uint32_t loco) {
    if (m_throttles.size() >= ThrottleSettings::MaximumThrottles)
        return nullptr;
    auto* throttle = new ThrottleWidget(m_rack);
    throttle->setRailway(m_railway);
    throttle->setPictures(m_pictures);
    throttle->setLocomotive(loco);
    connect(throttle, &ThrottleWidget::locomotiveChosen, this, &ThrottlePanel::save);
    connect(throttle, &ThrottleWidget::closeRequested, this, [this, throttle] { removeThrottle(throttle); });
    m_rack->add(throttle);
    m_throttles.push_back(throttle);
    renumber();
    save();
    updateEmptyState();
    if (!m_restoring)
        scrollTo(throttle);
    return throttle;
}

// A throttle the user adds after the others is scrolled into sight: its top, where its picker is, and as
// much of it as the panel shows. The rack lays it out and the scroll area takes the rack's new height first
// (both would otherwise wait for the event loop, and the scroll would end at the throttle before).
void ThrottlePanel::scrollTo(ThrottleWidget* throttle) {
    throttle->show(); // now, not when the event loop gets to it: the rack lays out visible widgets only
    m_rack->layout()->activate();
    m_rack->resize(m_rack->width(), std::max(m_rack->height(), m_rack->minimumSizeHint().height()));
    m_scroll->ensureWidgetVisible(throttle, 0, 0);
    if (throttle->height() > m_scroll->viewport()->height()) // taller than the panel: its top
        m_scroll->verticalScrollBar()->setValue(throttle->y());
}

void ThrottlePanel::removeThrottle(ThrottleWidget* throttle) {
    if (!m_throttles.removeOne(throttle))
        return;
    m_rack->remove(throttle);
    throttle->deleteLater();
    throttle->hide();
    renumber();
    save();
    updateEmptyState();
}

bool ThrottlePanel::focusThrottle(int number) {
    if (number < 1 || number > m_throttles.size())
        return false;
    ThrottleWidget* throttle = m_throttles[number - 1];
    m_scroll->ensureWidgetVisible(throttle);
    throttle->setFocus(Qt::ShortcutFocusReason);
    return true;
}

int ThrottlePanel::widthFor(int columns) const {
    const int throttle =
        m_throttles.isEmpty() ? ThrottleWidget().sizeHint().width() : m_throttles.first()->sizeHint().width();
    const QMargins margins = layout()->contentsMargins();
    const int scrollBar = style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, m_scroll);
    return margins.left() + columns * throttle + (columns - 1) * m_rack->spacing() + scrollBar +
           margins.right();
}

QString ThrottlePanel::emptyText() const {
    return m_emptyText->isHidden() ? QString() : m_emptyText->text();
}

void ThrottlePanel::renumber() {
    for (qsizetype i = 0; i < m_throttles.size(); ++i)
        m_throttles[i]->setNumber(int(i) + 1);
}

void ThrottlePanel::save() {
    if (m_restoring)
        return;
    QList<std::uint32_t> locomotives;
    for (const ThrottleWidget* throttle : m_throttles)
        locomotives.push_back(throttle->locomotive());
    ThrottleSettings::save(locomotives);
}

void ThrottlePanel::updateEmptyState() {
    m_add->setEnabled(m_throttles.size() < ThrottleSettings::MaximumThrottles);
    m_emptyText->setVisible(!m_railway || m_throttles.isEmpty());
    m_scroll->setVisible(!m_throttles.isEmpty());
    // Alone, the text and the offers below it sit in the middle of the page (the spare height above the text
    // and below the offers, the last item); above throttles, the text is one line.
    auto* box = static_cast<QBoxLayout*>(layout());
    box->setStretchFactor(m_emptyText, m_throttles.isEmpty() ? 1 : 0);
    box->setStretch(box->count() - 1, m_throttles.isEmpty() ? 1 : 0);
    retranslate();
    updateOffers();
}

// With no throttle open, a newcomer gets a button per locomotive to drive: the running ones first.
void ThrottlePanel::updateOffers() {
    QList<const model::Locomotive*> offered;
    if (m_railway && m_throttles.isEmpty()) {
        for (const model::Locomotive& loco : m_railway->state().locomotives().items())
            offered.push_back(&loco);
        std::stable_sort(
            offered.begin(), offered.end(),
            [](const model::Locomotive* a, const model::Locomotive* b) { return a->speed() > b->speed(); });
        offered = offered.mid(0, MaximumOffers);
    }
    while (m_driveButtons.size() > offered.size())
        delete m_driveButtons.takeLast();
    while (m_driveButtons.size() < offered.size()) {
        auto* button = new QPushButton(m_offers);
        button->setObjectName(QStringLiteral("driveLocomotive"));
        m_offers->layout()->addWidget(button);
        m_driveButtons.push_back(button);
    }
    for (qsizetype i = 0; i < offered.size(); ++i)
        offer(m_driveButtons[i], *offered[i]);
    m_offers->setVisible(!offered.isEmpty());
}

void ThrottlePanel::offer(QPushButton* button, const model::Locomotive& loco) {
    const quint32 uid = loco.id().value();
    button->setText(loco.speed() > 0 ? tr("Drive %1 (running)").arg(loco.displayName())
                                     : tr("Drive %1").arg(loco.displayName()));
    // The locomotive's picture, so that a newcomer recognises the train on the plan and the layout.
    button->setIconSize(OfferPicture);
    button->setIcon(m_pictures
                        ? QIcon(m_pictures->picture(loco.iconName(), OfferPicture, devicePixelRatioF()))
                        : QIcon());
    button->disconnect(this);
    connect(button, &QPushButton::clicked, this, [this, uid] {
        if (ThrottleWidget* throttle = addThrottle(uid))
            throttle->setFocus(Qt::OtherFocusReason);
    });
}

void ThrottlePanel::retranslate() {
    m_add->setText(tr("Add throttle"));
    m_add->setToolTip(tr("Open one more throttle (up to %1)").arg(ThrottleSettings::MaximumThrottles));
    // One short line: the full list is the tooltip and Help ▸ Keys, not four wrapped lines above the
    // throttles.
    m_keysHint->setText(tr("Alt+1…9: drive with the keyboard"));
    m_keysHint->setToolTip(tr("Alt+1…9: keyboard on a throttle · Up/Down or +/−: speed · R: direction · "
                              "0–9: F0–F9 · E: stop this loco · Space stays STOP for the layout"));
    m_emptyText->setText(!m_railway ? tr("No station connected: throttles drive once a station is ready.")
                                    : tr("No throttle open. Open one for a locomotive below, or with “Add "
                                         "throttle”."));
}

void ThrottlePanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        updateOffers(); // the offers' "Drive …" in the new language
    }
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
