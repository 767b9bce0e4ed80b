#include "shell/PassingMessage.h"

#include <QTimer>
#include <algorithm>

namespace stellwerk::ui {

PassingMessage::PassingMessage(QWidget* parent) : QLabel(parent), m_timeout(new QTimer(this)) {
    setObjectName(QStringLiteral("passingMessage"));
    setTextFormat(Qt::PlainText);
    setWordWrap(true);
    // It takes the room the permanent parts leave, however little: a long text wraps, it never pushes them.
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_timeout->setSingleShot(true);
    connect(m_timeout, &QTimer::timeout, this, &PassingMessage::clearMessage);
}

void PassingMessage::showMessage(const QString& text, int timeoutMs) {
    setText(text);
    setToolTip(text);
    fitHeight();
    if (timeoutMs > 0)
        m_timeout->start(timeoutMs);
    else
        m_timeout->stop();
}

void PassingMessage::clearMessage() {
    m_timeout->stop();
    showMessage(QString());
}

bool PassingMessage::isWhollyShown() const {
    return text().isEmpty() || (isVisible() && heightForWidth(width()) <= height());
}

void PassingMessage::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    fitHeight();
}

// The status bar is as tall as its tallest part: the message asks for the lines its text takes at this
// width, two at most (before the bar is laid out its width says nothing: one line then).
void PassingMessage::fitHeight() {
    const int line = fontMetrics().lineSpacing();
    const int needed = text().isEmpty() || width() < MinimumWidth
                           ? 0
                           : std::min(heightForWidth(width()), MaximumLines * line + 2);
    if (needed != minimumHeight())
        setMinimumHeight(needed);
}

} // namespace stellwerk::ui
