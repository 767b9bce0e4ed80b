#pragma once

#include <QList>
#include <QPointer>
#include <QWidget>
#include <cstdint>
#include <map>
#include <set>

class QComboBox;
class QLabel;
class QScrollArea;
class QToolButton;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

class TurnoutKey;
struct KeyFace;

// The turnout panel: the station's keyboard (magnetartikel.cs2) as pages of 16 keys, 1-16, 17-32, ...
// as on the CS2, so that every turnout, signal and uncoupler can be switched by hand, and any number
// without an article too. Positions come from the railway (what the station confirmed or another
// controller did); a switching is marked until the station confirms it.
class TurnoutPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TurnoutPanel)

public:
    static constexpr int KeysPerPage = 16;
    // The CS2 keyboard's 320 MM2 addresses; more pages when articles lie beyond them (DCC).
    static constexpr int MinimumPages = 20;

    explicit TurnoutPanel(QWidget* parent = nullptr);

    // The railway whose keyboard the panel shows (null: none).
    void setRailway(model::Railway* railway);

    // Pages count from 0; page n shows the numbers 16 n + 1 .. 16 n + 16.
    int page() const { return m_page; }
    int pageCount() const { return m_pageCount; }
    void setPage(int page);
    void nextPage();
    void previousPage();
    // The 16 keys of the page, in number order.
    QList<TurnoutKey*> keys() const { return m_keys; }
    // The key of a keyboard number on the current page, else null.
    TurnoutKey* keyFor(std::int64_t address) const;

    // As wide as four keys side by side with the keyboard's scroll bar, the width a side panel wants.
    QSize sizeHint() const override;

signals:
    void pageChanged(int page);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    QWidget* buildNavigation();
    void rebuild();
    void refreshKeys();
    void refresh(TurnoutKey* key, std::int64_t address);
    KeyFace faceOf(std::int64_t address) const;
    void showChanges(const QList<qint64>& addresses);
    void requestSwitch(qint64 address, int position);
    void switchingEnded(qint64 address, int position, bool acknowledged);
    void updatePagePicker();
    void retranslate();

    QPointer<model::Railway> m_railway;
    QToolButton* m_previous = nullptr;
    QToolButton* m_next = nullptr;
    QComboBox* m_pagePicker = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_emptyText = nullptr;
    QScrollArea* m_keyboard = nullptr; // the grid of keys, hidden without a railway
    QList<TurnoutKey*> m_keys;
    int m_page = 0;
    int m_pageCount = MinimumPages;
    // The number an article occupies beyond its first one -> the article's first number.
    std::map<std::int64_t, std::int64_t> m_owners;
    std::map<std::int64_t, int> m_pending; // switchings sent, not yet answered
    std::set<std::int64_t> m_unconfirmed;  // the station did not acknowledge the last switching
};

} // namespace stellwerk::ui
