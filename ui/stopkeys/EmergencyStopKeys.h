#pragma once

#include <QObject>
#include <QPointer>

class QKeyEvent;
class QWidget;

namespace stellwerk::ui {

// The keys that stop the whole layout, as the STOP key of a CS2 does. Space and an extra key
// (StopKeySettings, F12 unless chosen otherwise) stop from any widget of any window; Space is left to
// text fields while one is being typed in (a name with a space must stay possible). Escape belongs to
// popups and dialogs: it closes them and does nothing else. Only on the main window itself, with no
// popup, menu or dialog open and no table cell being edited, does Escape stop the layout too (and still
// reaches the widget, e.g. a search field that clears).
class EmergencyStopKeys final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(EmergencyStopKeys)

public:
    // Watches every key press of the application while it exists; `window` is where Escape may stop.
    explicit EmergencyStopKeys(QWidget* window, QObject* parent = nullptr);
    ~EmergencyStopKeys() override;

    // The extra key (Qt::Key_unknown: none).
    void setExtraKey(Qt::Key key) { m_extraKey = key; }
    Qt::Key extraKey() const { return m_extraKey; }

signals:
    void stopRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool isStopKey(const QKeyEvent& key) const;
    bool escapeMayStop() const;

    QPointer<QWidget> m_window;
    Qt::Key m_extraKey;
};

} // namespace stellwerk::ui
