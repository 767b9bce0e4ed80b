#pragma once

#include <QFrame>

class QLabel;

namespace stellwerk::ui {

// What the plan says about a block (BlockDescription) in a small popup beside the tile clicked, so that it
// covers little of the plan; it closes on a click elsewhere or Escape.
class BlockPopup final : public QFrame {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BlockPopup)

public:
    explicit BlockPopup(QWidget* parent = nullptr);

    // Shows the rich text with its top left at `globalPosition`, moved to stay on the screen.
    void showText(const QString& html, QPoint globalPosition);
    // The words shown, without their markup.
    QString plainText() const;

private:
    QLabel* m_text = nullptr;
};

} // namespace stellwerk::ui
