#pragma once

#include <QWidget>

class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTimer;
class QTreeWidget;

namespace stellwerk::ui {

// A workspace tab where a user pastes frames from a log, a trace or the protocol document and
// sees each one decoded (CS2 and M-CAN); the decoding itself is the core's busreading::FrameDescription.
class FrameDecoderPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(FrameDecoderPanel)

public:
    explicit FrameDecoderPanel(QWidget* parent = nullptr);

    // Replaces the input and decodes it at once (used by "Open capture" and by tests).
    void setInput(const QString& text);
    // Decodes the current input into the result table.
    void refresh();
    // Reads a capture file into the input; returns an error text, empty on success.
    QString loadCapture(const QString& path);

protected:
    void changeEvent(QEvent* event) override;

private:
    void openCapture();
    void retranslate();
    void updateSummary(int frames, int errors);

    QPlainTextEdit* m_input = nullptr;
    QTreeWidget* m_results = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_hint = nullptr;
    QPushButton* m_openButton = nullptr;
    QPushButton* m_clearButton = nullptr;
    QTimer* m_refreshTimer = nullptr;
    int m_frames = 0;
    int m_errors = 0;
};

} // namespace stellwerk::ui
