#include "trackplan/PageZoom.h"

#include "trackplan/TrackPageView.h"

#include <QEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QTabWidget>
#include <algorithm>
#include <cmath>

namespace stellwerk::ui {

PageZoom::PageZoom(QTabWidget* pages, QObject* parent) : QObject(parent), m_tabs(pages) {}

std::optional<std::int64_t> PageZoom::current() const {
    const QWidget* front = m_tabs ? m_tabs->currentWidget() : nullptr;
    for (auto it = m_pages.cbegin(); front && it != m_pages.cend(); ++it)
        if (it->scroll == front && it->view)
            return it.key();
    return std::nullopt;
}

int PageZoom::currentTile() const {
    const std::optional<std::int64_t> page = current();
    return page ? m_pages.value(*page).view->tileSize() : 0;
}

void PageZoom::zoomCurrent(int pixels) {
    if (const std::optional<std::int64_t> page = current())
        zoomTo(*page, pixels);
}

void PageZoom::fitCurrent() {
    if (const std::optional<std::int64_t> page = current())
        fit(*page);
}

bool PageZoom::isCurrentFitted() const {
    const std::optional<std::int64_t> page = current();
    return page && isFitted(*page);
}

void PageZoom::attach(std::int64_t pageId, TrackPageView* view, QScrollArea* scroll) {
    Page& page = m_pages[pageId];
    page.view = view;
    page.scroll = scroll;
    scroll->viewport()->installEventFilter(this);
    if (page.fitted)
        fitNow(page);
    else
        view->setTileSize(page.tile);
}

int PageZoom::stepped(int tile, int steps) {
    const int zoomed = int(tile * std::pow(1.2, steps));
    return steps > 0 ? std::max(tile + steps, zoomed) : std::min(tile + steps, zoomed);
}

void PageZoom::zoomTo(std::int64_t pageId, int pixels) {
    Page& page = m_pages[pageId];
    page.fitted = false;
    page.tile = std::clamp(pixels, MinimumTile, MaximumTile);
    if (page.view)
        page.view->setTileSize(page.tile);
}

void PageZoom::fit(std::int64_t pageId) {
    Page& page = m_pages[pageId];
    page.fitted = true;
    fitNow(page);
}

bool PageZoom::isFitted(std::int64_t pageId) const {
    return m_pages.value(pageId).fitted;
}

// A page's window changed size (or was shown for the first time): a fitted page fits again.
bool PageZoom::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Resize || event->type() == QEvent::Show)
        for (Page& page : m_pages)
            if (page.fitted && page.scroll && page.scroll->viewport() == watched)
                fitNow(page);
    return QObject::eventFilter(watched, event);
}

// A page not shown yet keeps its tile size: its window has no size to fit to until it is shown.
void PageZoom::fitNow(Page& page) {
    if (!page.view || !page.scroll || !page.scroll->isVisible())
        return;
    const QSize room =
        page.scroll->viewport()->size() - QSize(2 * TrackPageView::Margin, 2 * TrackPageView::Margin);
    if (room.isEmpty() || page.view->drawnCells().isEmpty())
        return;
    page.tile = fittingTile(*page.view, room);
    page.view->setTileSize(page.tile);
    centreDrawnPart(page);
}

// The largest tile size at which the page's drawn part, with the texts that run beyond their tiles, fits
// into `room`. The texts grow with the tiles: first in proportion, then a step at a time.
int PageZoom::fittingTile(const TrackPageView& view, QSize room) {
    const auto fits = [&view, room](int tile) {
        const QSize drawn = view.drawnArea(tile).size();
        return drawn.width() <= room.width() && drawn.height() <= room.height();
    };
    const QRect cells = view.drawnCells();
    const int byCells = std::clamp(std::min(room.width() / cells.width(), room.height() / cells.height()),
                                   MinimumTile, MaximumTile);
    const QSize drawn = view.drawnArea(byCells).size();
    int tile = std::max(MinimumTile, std::min({byCells, byCells * room.width() / std::max(1, drawn.width()),
                                               byCells * room.height() / std::max(1, drawn.height())}));
    while (tile > MinimumTile && !fits(tile))
        --tile;
    while (tile < byCells && fits(tile + 1))
        ++tile;
    return tile;
}

// The drawn part in the middle of the window; the empty rest of the grid stays reachable by scrolling.
void PageZoom::centreDrawnPart(const Page& page) {
    const QRect pixels = page.view->drawnArea(page.tile);
    const QSize room = page.scroll->viewport()->size();
    page.scroll->horizontalScrollBar()->setValue(pixels.center().x() - room.width() / 2);
    page.scroll->verticalScrollBar()->setValue(pixels.center().y() - room.height() / 2);
}

} // namespace stellwerk::ui
