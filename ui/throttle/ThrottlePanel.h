#pragma once

#include <QList>
#include <QPointer>
#include <QWidget>
#include <cstdint>

class QLabel;
class QPushButton;
class QScrollArea;

namespace stellwerk::model {
class Locomotive;
class Railway;
} // namespace stellwerk::model

namespace stellwerk::ui {

class LayoutStateBanner;
class LocomotivePictureBook;
class WrappingGrid;
class ThrottleWidget;

// The throttles page: several throttles side by side or stacked as the width allows, added and closed by
// the user, each driving one locomotive. Alt+1..Alt+9 put the keyboard on throttle 1..9. Which locomotives
// were open is remembered (ThrottleSettings) and opened again on the next start.
class ThrottlePanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ThrottlePanel)

public:
    // How many locomotives the empty page offers to drive.
    static constexpr int MaximumOffers = 4;

    explicit ThrottlePanel(QWidget* parent = nullptr);

    // The railway whose locomotives the throttles drive (null: none).
    void setRailway(model::Railway* railway);
    // The locomotives' pictures every throttle shows.
    void setPictures(LocomotivePictureBook* pictures);

    // A new throttle after the others, driving `loco` (0: the user picks one); null when all nine are open.
    ThrottleWidget* addThrottle(std::uint32_t loco = 0);
    void removeThrottle(ThrottleWidget* throttle);
    const QList<ThrottleWidget*>& throttles() const { return m_throttles; }
    // Puts the keyboard on throttle `number` (1-based); false if there is none.
    bool focusThrottle(int number);
    // What the page says while it has nothing to drive; empty while throttles drive.
    QString emptyText() const;
    // The buttons that open a throttle on a locomotive while none is open (running ones first).
    const QList<QPushButton*>& driveOffers() const { return m_driveButtons; }
    // The width that shows `columns` throttles side by side without scrolling sideways.
    int widthFor(int columns) const;
    // Says when the layout is stopped, halted or not reported; hidden while trains may run.
    LayoutStateBanner* layoutState() const { return m_banner; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void createShortcuts();
    void scrollTo(ThrottleWidget* throttle);
    void renumber();
    void save();
    void updateEmptyState();
    void updateOffers();
    void offer(QPushButton* button, const model::Locomotive& loco);
    void retranslate();

    QPointer<model::Railway> m_railway;
    QPointer<LocomotivePictureBook> m_pictures;
    QList<ThrottleWidget*> m_throttles;
    QPushButton* m_add;
    QLabel* m_keysHint;
    LayoutStateBanner* m_banner;
    QLabel* m_emptyText;
    QWidget* m_offers;
    QList<QPushButton*> m_driveButtons;
    QScrollArea* m_scroll;
    WrappingGrid* m_rack;
    bool m_restoring = false;
};

} // namespace stellwerk::ui
