#pragma once

#include <QLabel>
#include <QPointer>

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// A strip above the track plan and the throttles that says what the layout is doing when that is not
// "running": stopped (track power off), halted, track power not reported, or the whole state not
// reported while the station is silent or reconnecting. Hidden while the station reports power on.
class LayoutStateBanner final : public QLabel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LayoutStateBanner)

public:
    enum class Shows { Nothing, NotReported, PowerNotReported, Stopped, Halted };
    Q_ENUM(Shows)

    explicit LayoutStateBanner(QWidget* parent = nullptr);

    // The railway to follow (null: none, the banner hides).
    void setRailway(const model::Railway* railway);
    Shows shows() const { return m_shows; }

protected:
    void changeEvent(QEvent* event) override;

private:
    static Shows showsFor(const model::Railway* railway);
    void refresh();

    QPointer<const model::Railway> m_railway;
    Shows m_shows = Shows::Nothing;
};

} // namespace stellwerk::ui
