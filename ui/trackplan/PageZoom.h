#pragma once

#include <QHash>
#include <QObject>
#include <QPointer>
#include <cstdint>

class QScrollArea;

namespace stellwerk::ui {

class TrackPageView;

// Each page of the plan keeps its own zoom. A page first shows its drawn part filling the window (not
// the whole CS2 grid) and keeps fitting it while the window changes size, until the user zooms it;
// Fit goes back to that. The zoom of a page outlives a reload of the layout (pages are known by id).
class PageZoom final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PageZoom)

public:
    static constexpr int MinimumTile = 12;
    static constexpr int MaximumTile = 160;

    explicit PageZoom(QObject* parent = nullptr);

    // Takes care of a page's view inside its scroll area: the page's remembered zoom, or fitted.
    void attach(std::int64_t pageId, TrackPageView* view, QScrollArea* scroll);
    // Sets the page's tile size; the page no longer follows the window.
    void zoomTo(std::int64_t pageId, int pixels);
    // The page's drawn part fills its window, now and while the window changes size.
    void fit(std::int64_t pageId);
    bool isFitted(std::int64_t pageId) const;

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
    void centreDrawnPart(const Page& page);

    QHash<std::int64_t, Page> m_pages;
};

} // namespace stellwerk::ui
