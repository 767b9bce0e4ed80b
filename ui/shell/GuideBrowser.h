#pragma once

#include <QDialog>
#include <QSize>
#include <QString>

class QTextBrowser;

namespace stellwerk::ui {

// Help → User guide: the guide's pages (docs/guide, Markdown) in a window of their own, with their
// links and pictures, back and forward. The guide is read where it was installed
// (<prefix>/share/doc/stellwerk/guide beside the program's bin/), else from the source tree the program
// was built from (a developer's build).
class GuideBrowser final : public QDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(GuideBrowser)

public:
    // The guide's first page; empty when neither an installed nor a source copy is there.
    static QString startPage();

    explicit GuideBrowser(const QString& page, QWidget* parent = nullptr);
    QTextBrowser* browser() const { return m_browser; }

    // The size the guide opens at on a screen with `available` room: about two thirds of it, at least
    // 900 x 650 where that fits, never more than the screen.
    static QSize readableSize(const QSize& available);

    // Shows the guide, or says where it would be when it cannot be found.
    static void showGuide(QWidget* parent);

private:
    QTextBrowser* m_browser = nullptr;
};

} // namespace stellwerk::ui
