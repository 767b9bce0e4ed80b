#pragma once

#include <QLabel>

class QTimer;

namespace stellwerk::ui {

// A message that passes by on the left of the status bar (a station's problem and what to try). Where the
// station's line, the traffic and the track power leave it too little room it takes a second line instead
// of being cut off; it goes after its time, or when another replaces it.
class PassingMessage final : public QLabel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PassingMessage)

public:
    explicit PassingMessage(QWidget* parent = nullptr);

    // Shows `text` for `timeoutMs` milliseconds; 0: until it is replaced or cleared.
    void showMessage(const QString& text, int timeoutMs = 0);
    void clearMessage();
    // Whether all of the text is in sight.
    bool isWhollyShown() const;

    // Its height follows its width by itself (two lines at most); asked through the status bar's
    // layout instead, a wrapping label at a width of nothing makes the bar half as tall as the window.
    bool hasHeightForWidth() const override { return false; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    static constexpr int MaximumLines = 2;
    static constexpr int MinimumWidth = 120;
    void fitHeight();

    QTimer* m_timeout = nullptr;
};

} // namespace stellwerk::ui
