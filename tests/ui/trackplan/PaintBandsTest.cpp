// A page painted in bands on all cores is exactly the picture one painter would have painted: rendered
// into images (at an offset, at twice the pixel density, dimmed) and on screen in a scrolled window, where
// a band must not paint over the scroll bars or a neighbouring widget.

#include "trackplan/PaintBands.h"

#include "cs2config/TrackElementType.h"
#include "model/TrackLayout.h"
#include "station/StartupSequence.h"
#include "trackplan/PaintThreads.h"
#include "trackplan/TrackPageView.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QPainter>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QTest>
#include <QThread>
#include <gtest/gtest.h>
#include <memory>
#include <mutex>
#include <set>
#include <string>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

// Turns the bands on again whatever a test does.
struct BandsOff {
    BandsOff() { PaintBands::setEnabled(false); }
    ~BandsOff() { PaintBands::setEnabled(true); }
};

// A page of 30 x 24 tiles of every element type in every rotation, named, some occupied by a locomotive
// and one with a name the tags' font lacks (laid out by Qt, drawn on the GUI thread).
std::shared_ptr<const model::LayoutPage> bigPage() {
    station::DownloadedPage page;
    page.name = "bands";
    const auto types = cs2config::trackElementTypes();
    for (int i = 0; i < 30 * 24; ++i) {
        cs2config::TrackElement element;
        element.position = {0, std::uint8_t(i % 30), std::uint8_t(i / 30)};
        element.type = std::string(types[std::size_t(i) % types.size()].name);
        element.rotation = (i / int(types.size())) % 4;
        element.text = i == 77 ? "\xF0\x9F\x9A\x82"
                                 "7"
                               : "W" + std::to_string(i + 1);
        page.page.elements.push_back(element);
    }
    return std::make_shared<const model::LayoutPage>(model::TrackLayout({page}).pages()[0]);
}

std::unique_ptr<TrackPageView> viewOf(const std::shared_ptr<const model::LayoutPage>& page) {
    const auto look = [page](int tile) {
        const model::LayoutTile& t = page->tiles[std::size_t(tile)];
        TrackTileLook look{t.type,        t.category,    t.rotation, tile % 3 - 1,
                           tile % 5 == 0, tile % 7 == 0, t.text};
        if (look.occupied && t.category == cs2config::TrackCategory::Feedback)
            look.occupant = QStringLiteral("BR 218 %1").arg(tile);
        return look;
    };
    auto view = std::make_unique<TrackPageView>(page, look, [](int) { return QString(); });
    view->resize(view->sizeHint());
    return view;
}

// The view rendered into a picture of `size` at `offset`, at the given pixel density.
QImage rendered(TrackPageView& view, QSize size, QPoint offset, qreal ratio) {
    QImage image(size * ratio, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(ratio);
    image.fill(Qt::magenta);
    view.render(&image, offset);
    return image;
}

QImage renderedInOneBand(TrackPageView& view, QSize size, QPoint offset, qreal ratio) {
    const BandsOff off;
    return rendered(view, size, offset, ratio);
}

// Counts the paint events a widget gets.
struct PaintCounter : QObject {
    explicit PaintCounter(QWidget* widget) { widget->installEventFilter(this); }
    bool eventFilter(QObject*, QEvent* event) override {
        count += event->type() == QEvent::Paint;
        return false;
    }
    int count = 0;
};

bool severalCores() {
    return PaintThreads::count() > 1;
}

} // namespace

TEST(PaintBands, SplitsALargeAreaIntoOneBandPerCoreThatPaintOnlyTheirRowsAtOnce) {
    QImage image(400, 600, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setClipRect(QRect(10, 20, 300, 500));
    std::mutex lock;
    std::set<Qt::HANDLE> threads;
    QRegion covered;
    const int bands =
        PaintBands::paint(painter, QRect(10, 20, 300, 500), [&](QPainter& band, const QRect& part) {
            band.fillRect(QRect(0, 0, 400, 600), Qt::black); // more than the band: clipped to it
            const std::lock_guard guard(lock);
            threads.insert(QThread::currentThreadId());
            covered += part;
        });
    painter.end();
    EXPECT_EQ(bands, int(std::min<std::size_t>(PaintThreads::count(), 500 / PaintBands::MinimumHeight)));
    if (bands > 1) {
        EXPECT_GE(threads.size(), 2U) << "the bands are painted on more than one thread";
    }
    EXPECT_EQ(covered, QRegion(10, 20, 300, 500));
    EXPECT_EQ(image.pixel(9, 20), qRgb(255, 255, 255)) << "nothing outside the area";
    EXPECT_EQ(image.pixel(10, 19), qRgb(255, 255, 255));
    EXPECT_EQ(image.pixel(309, 519), qRgb(0, 0, 0));
    EXPECT_EQ(image.pixel(310, 519), qRgb(255, 255, 255));
    EXPECT_EQ(image.pixel(100, 520), qRgb(255, 255, 255));
}

TEST(PaintBands, ASmallAreaOrAPixmapIsPaintedInOneBandByThePainterItself) {
    QImage image(400, 600, QImage::Format_ARGB32_Premultiplied);
    QPainter onImage(&image);
    EXPECT_EQ(PaintBands::paint(onImage, QRect(0, 0, 400, PaintBands::MinimumHeight + 10),
                                [&](QPainter& band, const QRect&) { EXPECT_EQ(&band, &onImage); }),
              1);
    QImage printed(400, 600, QImage::Format_Mono); // not 32 bits a pixel: not split
    QPainter onMono(&printed);
    EXPECT_EQ(PaintBands::paint(onMono, QRect(0, 0, 400, 600), [](QPainter&, const QRect&) {}), 1);
    QImage turned(400, 600, QImage::Format_ARGB32_Premultiplied);
    QPainter rotated(&turned);
    rotated.rotate(90);
    EXPECT_EQ(PaintBands::paint(rotated, QRect(0, -400, 600, 400), [](QPainter&, const QRect&) {}), 1);
}

TEST(PaintBands, APageInBandsIsThePictureOneBandPaints) {
    if (!severalCores())
        GTEST_SKIP() << "one core: there is only one band";
    const auto page = bigPage();
    auto view = viewOf(page);
    const QImage one = renderedInOneBand(*view, view->size(), {}, 1.0);
    const QImage bands = rendered(*view, view->size(), {}, 1.0);
    EXPECT_TRUE(one == bands) << "the same pixels, tags, occupants and the label drawn by Qt included";
    EXPECT_NE(one.pixel(one.width() / 2, one.height() / 2), QColor(Qt::magenta).rgb()) << "painted at all";
}

TEST(PaintBands, AtAnOffsetAtTwiceThePixelDensityAndDimmedItIsTheSamePicture) {
    if (!severalCores())
        GTEST_SKIP() << "one core: there is only one band";
    const auto page = bigPage();
    auto view = viewOf(page);
    const QSize around = view->size() + QSize(40, 30);
    EXPECT_TRUE(renderedInOneBand(*view, around, {17, 9}, 1.0) == rendered(*view, around, {17, 9}, 1.0));
    EXPECT_TRUE(renderedInOneBand(*view, view->size(), {}, 2.0) == rendered(*view, view->size(), {}, 2.0));
    view->setDimmed(true);
    EXPECT_TRUE(renderedInOneBand(*view, view->size(), {}, 1.0) == rendered(*view, view->size(), {}, 1.0));
}

TEST(PaintBands, OnScreenABandPaintsNeitherOverTheScrollBarsNorBesideTheView) {
    if (!severalCores())
        GTEST_SKIP() << "one core: there is only one band";
    const auto page = bigPage();
    QWidget window;
    auto* layout = new QHBoxLayout(&window);
    auto* beside = new QLabel(QStringLiteral("beside"));
    beside->setAutoFillBackground(true);
    auto* scroll = new QScrollArea;
    TrackPageView* view = viewOf(page).release();
    scroll->setWidget(view);
    layout->addWidget(beside);
    layout->addWidget(scroll, 1);
    window.resize(900, 700);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    scroll->horizontalScrollBar()->setValue(scroll->horizontalScrollBar()->maximum() / 2);
    scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum() / 2);
    PaintCounter paints(view);
    const auto screenshot = [&] {
        const int before = paints.count;
        view->repaint();
        EXPECT_EQ(paints.count, before + 1);
        return window.screen()->grabWindow(window.winId()).toImage();
    };
    QImage one;
    {
        const BandsOff off;
        one = screenshot();
    }
    const QImage bands = screenshot();
    ASSERT_FALSE(one.isNull());
    EXPECT_TRUE(one == bands) << "the window's pixels, scroll bars and label included";
}
