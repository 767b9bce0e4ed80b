#include "keyboard/TurnoutPanel.h"

#include "common/NotReported.h"
#include "keyboard/TurnoutKey.h"
#include "model/Railway.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QScrollArea>
#include <QShortcut>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

namespace stellwerk::ui {
namespace {

constexpr int KeysPerRow = 4;

// The positions an article takes, in order: 0/1 for a turnout, 0/1/3 for Hp0/Hp1/Hp2, 0..31 for a turntable.
QList<int> positionsOf(const model::Accessory& accessory) {
    QList<int> positions;
    for (int position = 0; position < 32; ++position)
        if (accessory.acceptsPosition(position))
            positions.push_back(position);
    return positions;
}

} // namespace

TurnoutPanel::TurnoutPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("turnoutPanel"));
    setFocusPolicy(Qt::StrongFocus);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(buildNavigation());
    m_emptyText = new QLabel(this);
    m_emptyText->setObjectName(QStringLiteral("turnoutPanelEmpty"));
    m_emptyText->setAlignment(Qt::AlignCenter);
    m_emptyText->setEnabled(false);
    layout->addWidget(m_emptyText);
    // The keys keep their size; a short dock scrolls them instead of squeezing the names away.
    m_keyboard = new QScrollArea(this);
    m_keyboard->setWidgetResizable(true);
    m_keyboard->setFrameShape(QFrame::NoFrame);
    m_keyboard->installEventFilter(this);
    auto* keys = new QWidget(m_keyboard);
    m_keyboard->setWidget(keys);
    auto* grid = new QGridLayout(keys);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setSpacing(8);
    for (int i = 0; i < KeysPerPage; ++i) {
        auto* key = new TurnoutKey(keys);
        connect(key, &TurnoutKey::switchRequested, this, &TurnoutPanel::requestSwitch);
        grid->addWidget(key, i / KeysPerRow, i % KeysPerRow);
        m_keys.push_back(key);
    }
    grid->setRowStretch(KeysPerPage / KeysPerRow, 1);
    layout->addWidget(m_keyboard, 1);
    // Page Up/Down wherever the focus is inside the panel (keys, page picker).
    auto* down = new QShortcut(QKeySequence(Qt::Key_PageDown), this, this, &TurnoutPanel::nextPage);
    auto* up = new QShortcut(QKeySequence(Qt::Key_PageUp), this, this, &TurnoutPanel::previousPage);
    down->setContext(Qt::WidgetWithChildrenShortcut);
    up->setContext(Qt::WidgetWithChildrenShortcut);
    retranslate();
    rebuild();
}

QSize TurnoutPanel::sizeHint() const {
    const QMargins margins = layout()->contentsMargins();
    const auto* grid = static_cast<const QGridLayout*>(m_keyboard->widget()->layout());
    const int keys =
        KeysPerRow * m_keys.first()->sizeHint().width() + (KeysPerRow - 1) * grid->horizontalSpacing();
    const int scrollBar = style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, m_keyboard);
    return {margins.left() + keys + scrollBar + margins.right(), QWidget::sizeHint().height()};
}

QWidget* TurnoutPanel::buildNavigation() {
    auto* bar = new QWidget(this);
    auto* row = new QHBoxLayout(bar);
    row->setContentsMargins(0, 0, 0, 0);
    m_previous = new QToolButton(bar);
    m_previous->setObjectName(QStringLiteral("previousPage"));
    m_previous->setArrowType(Qt::LeftArrow);
    m_next = new QToolButton(bar);
    m_next->setObjectName(QStringLiteral("nextPage"));
    m_next->setArrowType(Qt::RightArrow);
    m_pagePicker = new QComboBox(bar);
    m_pagePicker->setObjectName(QStringLiteral("pagePicker"));
    m_summary = new QLabel(bar);
    m_summary->setObjectName(QStringLiteral("keyboardSummary"));
    m_summary->setEnabled(false);
    // "… · positions not reported" wraps rather than widening the keyboard beyond its dock.
    m_summary->setWordWrap(true);
    m_summary->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    row->addWidget(m_previous);
    row->addWidget(m_pagePicker);
    row->addWidget(m_next);
    row->addStretch(1);
    row->addWidget(m_summary);
    connect(m_previous, &QToolButton::clicked, this, &TurnoutPanel::previousPage);
    connect(m_next, &QToolButton::clicked, this, &TurnoutPanel::nextPage);
    connect(m_pagePicker, &QComboBox::activated, this, &TurnoutPanel::setPage);
    return bar;
}

void TurnoutPanel::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    m_pending.clear();
    m_unconfirmed.clear();
    if (m_railway) {
        connect(m_railway, &model::Railway::loaded, this, &TurnoutPanel::rebuild);
        connect(m_railway, &model::Railway::accessoriesChanged, this, &TurnoutPanel::showChanges);
        connect(m_railway, &model::Railway::addressesChanged, this, &TurnoutPanel::showChanges);
        connect(m_railway, &model::Railway::switchingEnded, this, &TurnoutPanel::switchingEnded);
        connect(m_railway, &model::Railway::stateReportedChanged, this, &TurnoutPanel::rebuild);
        connect(m_railway, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    rebuild();
}

// Which numbers the articles occupy, how many pages that needs; then the current page again.
void TurnoutPanel::rebuild() {
    m_owners.clear();
    std::int64_t last = 0;
    if (m_railway)
        for (const model::Accessory& accessory : m_railway->state().accessories().items()) {
            for (int n = 1; n < accessory.addressCount(); ++n)
                m_owners.emplace(accessory.id() + n, accessory.id());
            last = std::max<std::int64_t>(last, accessory.id() + accessory.addressCount() - 1);
        }
    m_pageCount = std::max<int>(MinimumPages, int((last + KeysPerPage - 1) / KeysPerPage));
    m_page = std::clamp(m_page, 0, m_pageCount - 1);
    int articles = m_railway ? int(m_railway->state().accessories().size()) : 0;
    m_summary->setText(
        !m_railway ? QString()
        : NotReported::applies(m_railway)
            ? tr("Articles on the keyboard: %1 · positions %2").arg(articles).arg(NotReported::word())
            : tr("Articles on the keyboard: %1").arg(articles));
    m_summary->setToolTip(NotReported::applies(m_railway) ? NotReported::reason() : QString());
    m_keyboard->setVisible(m_railway != nullptr);
    m_emptyText->setVisible(m_railway == nullptr);
    m_pagePicker->setEnabled(m_railway != nullptr);
    updatePagePicker();
    refreshKeys();
}

void TurnoutPanel::setPage(int page) {
    page = std::clamp(page, 0, m_pageCount - 1);
    if (page == m_page)
        return;
    m_page = page;
    m_pagePicker->setCurrentIndex(page);
    refreshKeys();
    emit pageChanged(page);
}

void TurnoutPanel::nextPage() {
    setPage(m_page + 1);
}

void TurnoutPanel::previousPage() {
    setPage(m_page - 1);
}

TurnoutKey* TurnoutPanel::keyFor(std::int64_t address) const {
    const std::int64_t first = std::int64_t(m_page) * KeysPerPage + 1;
    if (address < first || address >= first + KeysPerPage)
        return nullptr;
    return m_keys.at(qsizetype(address - first));
}

void TurnoutPanel::refreshKeys() {
    const std::int64_t first = std::int64_t(m_page) * KeysPerPage + 1;
    for (qsizetype i = 0; i < m_keys.size(); ++i)
        refresh(m_keys[i], first + i);
    m_previous->setEnabled(m_railway && m_page > 0);
    m_next->setEnabled(m_railway && m_page + 1 < m_pageCount);
}

void TurnoutPanel::refresh(TurnoutKey* key, std::int64_t address) {
    key->setFace(faceOf(address));
    // Greyed while not reported: a key shows the last position the station reported, and switching
    // from it would be a guess.
    key->setEnabled(m_railway != nullptr && m_railway->isStateReported());
    key->setPending(m_pending.contains(address));
    key->setUnconfirmed(m_unconfirmed.contains(address));
}

KeyFace TurnoutPanel::faceOf(std::int64_t address) const {
    KeyFace face;
    face.address = address;
    if (!m_railway)
        return face;
    if (const model::Accessory* accessory = m_railway->accessory(address)) {
        const auto* info = accessory->typeInfo();
        face.role = KeyFace::Role::Article;
        face.name = accessory->name().isEmpty() ? tr("Article %1").arg(address) : accessory->name();
        face.type = info ? QString::fromUtf8(info->description.data(), qsizetype(info->description.size()))
                         : accessory->type();
        face.kind = AccessoryIcon::kindOf(accessory->type());
        face.position = accessory->position();
        face.positions = positionsOf(*accessory);
        return face;
    }
    if (const auto owner = m_owners.find(address); owner != m_owners.end()) {
        const model::Accessory* article = m_railway->accessory(owner->second);
        face.role = KeyFace::Role::PartOfArticle;
        face.owner = owner->second;
        face.ownerName = article ? article->name() : QString();
        face.kind = article ? AccessoryIcon::kindOf(article->type()) : AccessoryIcon::Kind::Plain;
        return face;
    }
    face.position = m_railway->addressPosition(address).value_or(-1);
    return face;
}

void TurnoutPanel::showChanges(const QList<qint64>& addresses) {
    for (const qint64 address : addresses) {
        m_unconfirmed.erase(address);
        if (TurnoutKey* key = keyFor(address))
            refresh(key, address);
    }
}

void TurnoutPanel::requestSwitch(qint64 address, int position) {
    if (!m_railway)
        return;
    m_pending[address] = position;
    m_unconfirmed.erase(address);
    if (TurnoutKey* key = keyFor(address))
        refresh(key, address);
    if (m_railway->accessory(address))
        m_railway->switchAccessory(address, position);
    else
        m_railway->switchAddress(address, position);
}

void TurnoutPanel::switchingEnded(qint64 address, int, bool acknowledged) {
    m_pending.erase(address);
    if (acknowledged)
        m_unconfirmed.erase(address);
    else
        m_unconfirmed.insert(address);
    if (TurnoutKey* key = keyFor(address))
        refresh(key, address);
}

void TurnoutPanel::updatePagePicker() {
    m_pagePicker->clear();
    for (int page = 0; page < m_pageCount; ++page)
        m_pagePicker->addItem(
            tr("Page %1: %2–%3").arg(page + 1).arg(page * KeysPerPage + 1).arg((page + 1) * KeysPerPage));
    m_pagePicker->setCurrentIndex(m_page);
}

// The scroll area would use Page Up/Down to scroll; on the keyboard they turn pages.
bool TurnoutPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_keyboard && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_PageDown || key == Qt::Key_PageUp) {
            keyPressEvent(static_cast<QKeyEvent*>(event));
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void TurnoutPanel::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_PageDown) {
        nextPage();
        return;
    }
    if (event->key() == Qt::Key_PageUp) {
        previousPage();
        return;
    }
    QWidget::keyPressEvent(event);
}

void TurnoutPanel::retranslate() {
    m_emptyText->setText(tr("The keyboard appears when a station is connected."));
    m_previous->setToolTip(tr("Previous page (Page Up)"));
    m_next->setToolTip(tr("Next page (Page Down)"));
    m_pagePicker->setToolTip(tr("Keyboard page: 16 addresses each, as on the Central Station"));
}

void TurnoutPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        rebuild();
    }
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
