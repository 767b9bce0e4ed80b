#pragma once

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSize>
#include <cstdint>
#include <optional>

class QScrollArea;
class QTabWidget;

namespace stellwerk::ui {

class TrackPageView;

// Each page of the plan keeps its own zoom. A page first shows its drawn part, texts that run beyond their
// tiles included, filling the window (not the whole CS2 grid) and keeps fitting it while the window
// changes size, until the user zooms it; Fit goes back to that. The zoom of a page outlives a reload of the
// layout (pages are known by id).
class PageZoom final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PageZoom)

public:
    static constexpr int MinimumTile = 12;
    static constexpr int MaximumTile = 160;

    // `pages` shows the pages' scroll areas as tabs: the one in front is the current page.
    explicit PageZoom(QTabWidget* pages, QObject* parent = nullptr);

    // Takes care of a page's view inside its scroll area: the page's remembered zoom, or fitted.
    void attach(std::int64_t pageId, TrackPageView* view, QScrollArea* scroll);
    // `tile` zoomed by `steps` (negative: out) of 20 % each, at least a pixel per step.
    static int stepped(int tile, int steps);
    // Sets the page's tile size; the page no longer follows the window.
    void zoomTo(std::int64_t pageId, int pixels);
    // The page's drawn part fills its window, now and while the window changes size.
    void fit(std::int64_t pageId);
    bool isFitted(std::int64_t pageId) const;

    // The same for the page in front (nothing while no page is shown).
    int currentTile() const;
    void zoomCurrent(int pixels);
    void fitCurrent();
    bool isCurrentFitted() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Page {
        QPointer<TrackPageView> view;
        QPointer<QScrollArea> scroll;
        int tile = 40;
        bool fitted = true;
    };

    void fitNow(Page& page);
    static int fittingTile(const TrackPageView& view, QSize room);
    void centreDrawnPart(const Page& page);

    std::optional<std::int64_t> current() const;

    QPointer<QTabWidget> m_tabs;
    QHash<std::int64_t, Page> m_pages;
};

} // namespace stellwerk::ui
