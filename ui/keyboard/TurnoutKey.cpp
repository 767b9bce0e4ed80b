#include "keyboard/TurnoutKey.h"

#include "common/Contrast.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QImage>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QToolButton>
#include <QVBoxLayout>

namespace stellwerk::ui {
namespace {

// Four keys side by side fit a laptop's side panel, as on the CS2's keyboard page.
constexpr int KeyWidth = 104;
constexpr int FaceHeight = 116;
constexpr int ButtonRowHeight = 28;
constexpr int NameLines = 2;
constexpr int DrawingOverhang = 8; // how far a drawing may reach beyond its square
const QColor PendingAmber{0xe0, 0x9a, 0x1a};
const QColor UnconfirmedRed{0xd0, 0x36, 0x36};

QIcon colourChip(const QColor& colour) {
    QPixmap pixmap(12, 12);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(0x20, 0x20, 0x20), 1));
    painter.setBrush(colour);
    painter.drawEllipse(QRectF(1, 1, 10, 10));
    return QIcon(pixmap);
}

} // namespace

TurnoutKey::TurnoutKey(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("turnoutKey"));
    setAttribute(Qt::WA_Hover);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, FaceHeight, 6, 6);
    layout->setSpacing(0);
    m_buttonRow = new QHBoxLayout;
    m_buttonRow->setSpacing(3);
    layout->addLayout(m_buttonRow);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

QSize TurnoutKey::sizeHint() const {
    return {KeyWidth, FaceHeight + ButtonRowHeight + 6};
}

QSize TurnoutKey::minimumSizeHint() const {
    return {KeyWidth - 8, FaceHeight + ButtonRowHeight + 6};
}

void TurnoutKey::setFace(const KeyFace& face) {
    const bool otherButtons = face.address != m_face.address || face.role != m_face.role ||
                              face.positions != m_face.positions || face.kind != m_face.kind;
    m_face = face;
    if (otherButtons)
        rebuildButtons();
    updateButtons();
    setFocusPolicy(toggles() ? Qt::StrongFocus : Qt::NoFocus);
    setCursor(toggles() ? Qt::PointingHandCursor : Qt::ArrowCursor);
    updateToolTip();
    update();
}

void TurnoutKey::setPending(bool pending) {
    if (m_pending == pending)
        return;
    m_pending = pending;
    updateToolTip();
    update();
}

void TurnoutKey::setUnconfirmed(bool unconfirmed) {
    if (m_unconfirmed == unconfirmed)
        return;
    m_unconfirmed = unconfirmed;
    updateToolTip();
    update();
}

bool TurnoutKey::toggles() const {
    return m_face.role == KeyFace::Role::Article && m_face.positions.size() == 2;
}

QString TurnoutKey::positionText() const {
    if (m_face.role == KeyFace::Role::PartOfArticle)
        return tr("part of %1").arg(m_face.owner);
    if (m_face.role == KeyFace::Role::Address && m_face.position < 0)
        return tr("not known");
    return AccessoryIcon::positionName(m_face.kind, m_face.position);
}

int TurnoutKey::nextPosition() const {
    const QList<int>& positions = m_face.positions;
    const qsizetype at = positions.indexOf(m_face.position);
    return at < 0 ? positions.value(1, 1) : positions.at((at + 1) % positions.size());
}

void TurnoutKey::clearButtons() {
    qDeleteAll(m_buttons);
    m_buttons.clear();
    delete m_menuButton;
    m_menuButton = nullptr;
}

// Red and green buttons for a plain number; a menu of the positions for three and more, which would not
// fit as buttons side by side on a key.
void TurnoutKey::rebuildButtons() {
    clearButtons();
    if (m_face.role == KeyFace::Role::PartOfArticle)
        return;
    if (m_face.role == KeyFace::Role::Address) {
        for (const int position : m_face.positions)
            addChipButton(position);
        return;
    }
    if (m_face.positions.size() <= 2)
        return;
    m_menuButton = new QToolButton(this);
    m_menuButton->setObjectName(QStringLiteral("positionMenu"));
    m_menuButton->setPopupMode(QToolButton::InstantPopup);
    m_menuButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_menuButton->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    auto* menu = new QMenu(m_menuButton);
    for (const int position : m_face.positions) {
        QAction* action = menu->addAction(
            QString(), this, [this, position] { emit switchRequested(m_face.address, position); });
        action->setCheckable(true);
    }
    m_menuButton->setMenu(menu);
    m_buttonRow->addWidget(m_menuButton);
}

// A colour chip without text: the CS2's red and green halves of a key. The name is in the tooltip.
void TurnoutKey::addChipButton(int position) {
    auto* button = new QToolButton(this);
    button->setCheckable(true);
    button->setIcon(colourChip(AccessoryIcon::positionColour(position)));
    button->setToolButtonStyle(Qt::ToolButtonIconOnly);
    button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    button->setMinimumWidth(0);
    connect(button, &QToolButton::clicked, this, [this, position] {
        updateButtons(); // the check mark follows the station, not the click
        emit switchRequested(m_face.address, position);
    });
    m_buttonRow->addWidget(button);
    m_buttons.push_back(button);
}

void TurnoutKey::updateButtons() {
    for (qsizetype i = 0; i < m_buttons.size(); ++i) {
        const int position = m_face.positions.value(i);
        const QString name = AccessoryIcon::positionName(m_face.kind, position);
        m_buttons[i]->setText(name);
        m_buttons[i]->setToolTip(tr("Switch %1 to %2").arg(m_face.address).arg(name));
        m_buttons[i]->setChecked(position == m_face.position);
    }
    if (!m_menuButton)
        return;
    m_menuButton->setText(m_face.position < 0 ? tr("Position") : positionText());
    m_menuButton->setToolTip(tr("Switch %1 to another position").arg(m_face.address));
    const QList<QAction*> actions = m_menuButton->menu()->actions();
    for (qsizetype i = 0; i < actions.size(); ++i) {
        const int position = m_face.positions.value(int(i));
        actions[i]->setText(AccessoryIcon::positionName(m_face.kind, position));
        actions[i]->setChecked(position == m_face.position);
    }
}

void TurnoutKey::updateToolTip() {
    QString text;
    switch (m_face.role) {
    case KeyFace::Role::Article:
        text = tr("%1 (%2), address %3: %4")
                   .arg(m_face.name, m_face.type)
                   .arg(m_face.address)
                   .arg(positionText());
        break;
    case KeyFace::Role::Address:
        text = tr("Address %1 has no article; it switches as an MM2 address").arg(m_face.address);
        break;
    case KeyFace::Role::PartOfArticle:
        text = tr("Address %1 belongs to %2, which starts on %3")
                   .arg(m_face.address)
                   .arg(m_face.ownerName)
                   .arg(m_face.owner);
        break;
    }
    setAccessibleName(text);
    if (m_pending)
        text += QLatin1Char('\n') + tr("Switching: waiting for the station to confirm");
    else if (m_unconfirmed)
        text += QLatin1Char('\n') + tr("The station did not confirm the last switching");
    setToolTip(text);
}

QRectF TurnoutKey::faceRect() const {
    return QRectF(rect()).adjusted(1.5, 1.5, -1.5, -1.5);
}

QColor TurnoutKey::frameColour() const {
    if (m_pending)
        return PendingAmber;
    if (m_unconfirmed)
        return UnconfirmedRed;
    if (hasFocus())
        return palette().color(QPalette::Highlight);
    return palette().color(QPalette::Mid);
}

// Greyed: part of another article, or a position nobody vouches for now.
bool TurnoutKey::greyed() const {
    return m_face.role == KeyFace::Role::PartOfArticle || !isEnabled();
}

QColor TurnoutKey::faceColour() const {
    const bool part = m_face.role == KeyFace::Role::PartOfArticle;
    const QColor background = palette().color(QPalette::Active, part ? QPalette::Window : QPalette::Button);
    if (toggles() && underMouse())
        return background.lighter(
            palette().color(QPalette::Active, QPalette::Window).lightness() < 128 ? 130 : 106);
    return background;
}

// The palette's colour for `role`; greyed, paler but still readable on the face (the style's disabled grey
// is too pale for that).
QColor TurnoutKey::textColour(QPalette::ColorRole role) const {
    const QColor colour = palette().color(QPalette::Active, role);
    return greyed() ? Contrast::faded(colour, faceColour(), Contrast::ForText) : colour;
}

void TurnoutKey::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF face = faceRect();
    QPen frame(frameColour(), m_pending || m_unconfirmed ? 3 : 1);
    if (m_unconfirmed && !m_pending)
        frame.setStyle(Qt::DashLine);
    painter.setPen(frame);
    painter.setBrush(faceColour());
    painter.drawRoundedRect(face, 6, 6);
    const int iconSize = hasButtons() ? 44 : 56;
    paintDrawing(painter, QRectF(face.center().x() - iconSize / 2.0, face.top() + 20, iconSize, iconSize));
    paintTexts(painter, face);
}

// The drawing in the usable colours; greyed, the whole drawing at once made paler (as one layer, so that
// overlapping parts do not add up darker than the texts), as far as it stays 3:1 on the face.
void TurnoutKey::paintDrawing(QPainter& painter, const QRectF& icon) const {
    QPalette colours = palette();
    colours.setCurrentColorGroup(QPalette::Active);
    const int position = m_face.role == KeyFace::Role::PartOfArticle ? -1 : m_face.position;
    if (!greyed()) {
        AccessoryIcon::paint(painter, icon, m_face.kind, position, colours);
        return;
    }
    const QRectF room = icon.adjusted(-DrawingOverhang, -DrawingOverhang, DrawingOverhang, DrawingOverhang);
    const qreal ratio = devicePixelRatioF();
    QImage layer((room.size() * ratio).toSize(), QImage::Format_ARGB32_Premultiplied);
    layer.setDevicePixelRatio(ratio);
    layer.fill(Qt::transparent);
    QPainter onLayer(&layer);
    onLayer.setRenderHint(QPainter::Antialiasing);
    AccessoryIcon::paint(onLayer, icon.translated(-room.topLeft()), m_face.kind, position, colours);
    onLayer.end();
    painter.setOpacity(Contrast::keptFor(colours.color(QPalette::Text), faceColour(), Contrast::ForDrawings));
    painter.drawImage(room.topLeft(), layer);
    painter.setOpacity(1);
}

// The number top left, a mark top right while switching, name (two lines) and position under the drawing.
void TurnoutKey::paintTexts(QPainter& painter, const QRectF& face) const {
    QFont bold = font();
    bold.setBold(true);
    painter.setFont(bold);
    painter.setPen(textColour(QPalette::ButtonText));
    const QRectF top(face.left() + 7, face.top() + 3, face.width() - 14, 18);
    painter.drawText(top, Qt::AlignLeft | Qt::AlignVCenter, QString::number(m_face.address));
    if (m_pending || m_unconfirmed) {
        painter.setPen(m_pending ? PendingAmber : UnconfirmedRed);
        painter.drawText(top, Qt::AlignRight | Qt::AlignVCenter,
                         m_pending ? QStringLiteral("…") : QStringLiteral("!"));
    }
    const QFont nameFont = m_face.role == KeyFace::Role::Article ? bold : font();
    const QFontMetrics metrics(nameFont);
    const int lineHeight = metrics.height();
    const double textBottom = hasButtons() ? face.top() + FaceHeight - 2 : face.bottom() - 6;
    const QRectF positionRect(face.left() + 4, textBottom - lineHeight, face.width() - 8, lineHeight);
    const KeyName name = nameLines(metrics, int(positionRect.width()));
    painter.setFont(nameFont);
    painter.setPen(
        textColour(m_face.role == KeyFace::Role::Article ? QPalette::ButtonText : QPalette::PlaceholderText));
    QRectF line = positionRect.translated(0, -lineHeight * double(name.lines.size()));
    for (const QString& text : name.lines) {
        painter.drawText(line, Qt::AlignCenter, text);
        line.translate(0, lineHeight);
    }
    painter.setFont(font());
    const bool known = m_face.role != KeyFace::Role::PartOfArticle && m_face.position >= 0;
    painter.setPen(textColour(known ? QPalette::ButtonText : QPalette::PlaceholderText));
    painter.drawText(
        positionRect, Qt::AlignCenter,
        QFontMetrics(font()).elidedText(positionText(), Qt::ElideRight, int(positionRect.width())));
}

QString TurnoutKey::shownName() const {
    switch (m_face.role) {
    case KeyFace::Role::Address:
        return tr("no article");
    case KeyFace::Role::PartOfArticle:
        return m_face.ownerName;
    case KeyFace::Role::Article:
        break;
    }
    return m_face.name;
}

// The name broken at spaces into at most two lines of `width`; what still does not fit is elided.
TurnoutKey::KeyName TurnoutKey::nameLines(const QFontMetrics& metrics, int width) const {
    KeyName name;
    QString rest = shownName().simplified();
    while (!rest.isEmpty() && name.lines.size() < NameLines) {
        const bool last = name.lines.size() == NameLines - 1;
        qsizetype cut = rest.size();
        while (!last && metrics.horizontalAdvance(rest.left(cut)) > width) {
            const qsizetype space = rest.lastIndexOf(QLatin1Char(' '), cut - 1);
            if (space <= 0)
                break; // one word wider than the key: the line elides it
            cut = space;
        }
        QString line = rest.left(cut);
        rest = rest.mid(cut).trimmed();
        if (metrics.horizontalAdvance(line) > width || (last && !rest.isEmpty())) {
            line = metrics.elidedText(line + (rest.isEmpty() ? QString() : QStringLiteral(" ") + rest),
                                      Qt::ElideRight, width);
            name.elided = true;
            rest.clear();
        }
        name.lines.push_back(line);
    }
    return name;
}

bool TurnoutKey::isTextElided() const {
    QFont nameFont = font();
    nameFont.setBold(m_face.role == KeyFace::Role::Article);
    const int width = int(faceRect().width()) - 8;
    return nameLines(QFontMetrics(nameFont), width).elided ||
           fontMetrics().horizontalAdvance(positionText()) > width;
}

bool TurnoutKey::hasButtons() const {
    return !m_buttons.isEmpty() || m_menuButton;
}

void TurnoutKey::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && toggles() && rect().contains(event->position().toPoint())) {
        emit switchRequested(m_face.address, nextPosition());
        event->accept();
        return;
    }
    QWidget::mouseReleaseEvent(event);
}

// Enter switches a focused key; Space is not used: in the main window it stops the whole layout.
void TurnoutKey::keyPressEvent(QKeyEvent* event) {
    if (toggles() && (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter)) {
        emit switchRequested(m_face.address, nextPosition());
        return;
    }
    QWidget::keyPressEvent(event);
}

void TurnoutKey::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        updateButtons();
        updateToolTip();
        update();
    }
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
