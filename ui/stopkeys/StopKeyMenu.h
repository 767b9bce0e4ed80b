#pragma once

#include <QMenu>

class QActionGroup;

namespace stellwerk::ui {

// Station → Extra STOP key: which key besides Space stops the layout from anywhere (StopKeySettings).
class StopKeyMenu final : public QMenu {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(StopKeyMenu)

public:
    StopKeyMenu(Qt::Key current, QWidget* parent);

    Qt::Key current() const;

signals:
    void keyChosen(Qt::Key key);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();

    QActionGroup* m_group;
};

} // namespace stellwerk::ui
