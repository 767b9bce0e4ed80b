#pragma once

#include "keyboard/AccessoryIcon.h"

#include <QList>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <cstdint>

class QFontMetrics;
class QHBoxLayout;
class QToolButton;

namespace stellwerk::ui {

// What one key of the keyboard shows: an article, a keyboard number without one, or the second
// address of an article that starts on an earlier number.
struct KeyFace {
    enum class Role { Article, Address, PartOfArticle };

    Role role = Role::Address;
    std::int64_t address = 0; // the keyboard number, 1-based
    QString name;
    QString type; // the type's description, for the tooltip
    AccessoryIcon::Kind kind = AccessoryIcon::Kind::Plain;
    int position = -1; // -1: not known
    QList<int> positions{0, 1};
    std::int64_t owner = 0; // PartOfArticle: the number the article starts on
    QString ownerName;
};

// One key of the turnout panel, like a key of the CS2 keyboard: the article's drawing in its position,
// its number, name and position. A two-position article switches over with a click (or Enter); one with
// more positions offers them in a menu under its drawing; a number without an article has a red and a
// green button. A switching the station has not confirmed yet is framed in amber, one
// it did not confirm in red.
class TurnoutKey final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TurnoutKey)

public:
    explicit TurnoutKey(QWidget* parent = nullptr);

    void setFace(const KeyFace& face);
    const KeyFace& face() const { return m_face; }
    std::int64_t address() const { return m_face.address; }
    // Waiting for the station's acknowledgement of a switching.
    void setPending(bool pending);
    bool pending() const { return m_pending; }
    // The last switching was not acknowledged.
    void setUnconfirmed(bool unconfirmed);
    bool unconfirmed() const { return m_unconfirmed; }
    // True when a click on the key switches it over (two-position articles).
    bool toggles() const;
    // The red and green buttons of a number without an article.
    QList<QToolButton*> positionButtons() const { return m_buttons; }
    // The menu of an article with more than two positions, named after the current one.
    QToolButton* positionMenuButton() const { return m_menuButton; }
    // True when the key's name does not fit its two lines, or its position its line, and is shortened.
    bool isTextElided() const;
    // The text under the name: "Straight", "Hp0", "part of 4" ...
    QString positionText() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void switchRequested(qint64 address, int position);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    struct KeyName {
        QStringList lines;
        bool elided = false;
    };

    void rebuildButtons();
    void addChipButton(int position);
    bool hasButtons() const;
    QString shownName() const;
    KeyName nameLines(const QFontMetrics& metrics, int width) const;
    void clearButtons();
    void updateButtons();
    void updateToolTip();
    QRectF faceRect() const;
    QColor frameColour() const;
    QColor faceColour() const;
    bool greyed() const;
    QColor textColour(QPalette::ColorRole role) const;
    void paintDrawing(QPainter& painter, const QRectF& icon) const;
    void paintTexts(QPainter& painter, const QRectF& face) const;
    int nextPosition() const;

    KeyFace m_face;
    bool m_pending = false;
    bool m_unconfirmed = false;
    QHBoxLayout* m_buttonRow = nullptr;
    QList<QToolButton*> m_buttons;
    QToolButton* m_menuButton = nullptr;
};

} // namespace stellwerk::ui
