#pragma once

#include <QObject>
#include <QPointer>

class QBoxLayout;
class QSplitter;
class QWidget;

namespace stellwerk::ui {

// Puts a panel's two parts side by side while the panel is at least `width` wide and one above the other
// when it is narrower, as in a side dock on a laptop, so that neither part needs a sideways scroll bar.
class SideBySide final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(SideBySide)

public:
    // Follows `panel`'s width from now on; owned by the panel.
    static void arrange(QWidget* panel, QSplitter* parts, int width);
    static void arrange(QWidget* panel, QBoxLayout* parts, int width);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    SideBySide(QWidget* panel, int width);
    void follow(int panelWidth);

    QPointer<QSplitter> m_splitter;
    QBoxLayout* m_layout = nullptr;
    int m_width;
};

} // namespace stellwerk::ui
