#pragma once

#include <QFrame>
#include <functional>

class QLabel;
class QToolButton;

namespace stellwerk::ui {

// A red bar that says what went wrong with a file or a layout (or an amber one for what the user may want
// to put right, such as the problems of a track plan's drawing): its words are made again when the
// language changes (a problem is kept as a way to describe it, not as finished text), a long one folds
// to its first line, and the user can dismiss it until the next problem comes.
class ProblemBar final : public QFrame {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ProblemBar)

public:
    // Describes the problem in the language chosen now; an empty text means there is none.
    using Describe = std::function<QString()>;

    explicit ProblemBar(QWidget* parent = nullptr);

    // Error: red with white text (something failed). Notice: amber with black text (worth putting right).
    enum class Tone { Error, Notice };
    void setTone(Tone tone);
    Tone tone() const { return m_tone; }

    // A problem of more lines than this starts folded, so that it does not cover the plan.
    static constexpr int UnfoldedLines = 3;

    // Shows the problem `describe` says (folded when it is long); an empty description hides the bar.
    void setProblem(Describe describe);
    void clear() { setProblem({}); }
    // The whole problem in the current language; empty while the bar is hidden or dismissed.
    QString text() const;
    // What the bar shows now: the whole text, or its first line while folded.
    QString shownText() const;

    bool isFolded() const { return m_folded; }
    void setFolded(bool folded);
    // Hides the bar until the next setProblem().
    void dismiss();

protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    bool hasMoreLines() const;
    void refresh();
    void retranslate();

    Describe m_describe;
    Tone m_tone = Tone::Error;
    QString m_text;
    bool m_folded = false;
    QLabel* m_label = nullptr;
    QToolButton* m_fold = nullptr;
    QToolButton* m_dismiss = nullptr;
};

} // namespace stellwerk::ui
