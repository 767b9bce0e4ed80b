#include "trackplan/TileTag.h"

#include "model/TrackLayout.h"
#include "trackplan/NameElision.h"
#include "trackplan/TrackColors.h"

#include <QFontMetrics>
#include <QHash>
#include <QPainter>
#include <QRawFont>
#include <algorithm>
#include <cmath>

namespace stellwerk::ui {
namespace {

using Category = cs2config::TrackCategory;

bool carriesName(Category category) {
    switch (category) {
    case Category::Turnout:
    case Category::Signal:
    case Category::Feedback:
    case Category::RouteButton:
    case Category::Uncoupler:
    case Category::Output:
    case Category::Turntable:
    case Category::TransferTable:
        return true;
    default:
        return false; // track has none; texts and page links draw their own
    }
}

// One character of a tag: its glyph in the tags' font and how far it moves the pen.
struct Glyph {
    quint32 index = 0;
    QPointF advance;
};

// The glyph tables of the tags' font, with each character looked up once: every tag of a zoom shares one
// font, so one is kept, and the names of a page share a few dozen characters between them.
class GlyphTable {
public:
    const QRawFont& font(const QFont& font) {
        if (!m_raw.isValid() || m_font != font) {
            m_font = font;
            m_raw = QRawFont::fromFont(font);
            m_glyphs.clear();
            m_lineHeight = QFontMetrics(font).height();
        }
        return m_raw;
    }
    // The character's glyph; index 0 when the font lacks it or it is half of a surrogate pair.
    Glyph glyph(QChar character) {
        const auto known = m_glyphs.constFind(character.unicode());
        if (known != m_glyphs.cend())
            return *known;
        Glyph glyph;
        if (!character.isSurrogate()) {
            const QList<quint32> indexes = m_raw.glyphIndexesForString(QString(character));
            if (indexes.size() == 1 && indexes[0] != 0) {
                glyph.index = indexes[0];
                glyph.advance = m_raw.advancesForGlyphIndexes(indexes).value(0);
            }
        }
        return *m_glyphs.insert(character.unicode(), glyph);
    }

    // QFontMetrics::height() of the font last given to font().
    int lineHeight() const { return m_lineHeight; }

private:
    QFont m_font;
    QRawFont m_raw;
    int m_lineHeight = 0;
    QHash<char16_t, Glyph> m_glyphs;
};

GlyphTable& glyphTable() {
    static GlyphTable table;
    return table;
}

} // namespace

TileTag::TileTag(const model::LayoutTile& tile, const QRect& cell, const QFont& font) : m_font(font) {
    const QString name = tile.text.trimmed();
    if (name.isEmpty() || !carriesName(tile.category) || cell.width() < MinimumTile)
        return;
    // Every name stays on its tile: neighbours (a signal beside its contact, buttons in a row) carry theirs.
    // A route button's goes under the button.
    place(name, cell.topLeft() + QPoint(1, 1), cell.width() - 2);
    if (tile.category == Category::RouteButton)
        m_rect.moveTo(cell.center().x() - m_rect.width() / 2, cell.bottom() + 1 - m_rect.height());
}

TileTag TileTag::occupant(const QString& name, const QRect& cell, const QFont& font) {
    TileTag tag(font);
    tag.m_occupant = true;
    if (!name.trimmed().isEmpty() && cell.width() >= MinimumTile)
        tag.place(name.trimmed(), cell.topLeft() + QPoint(1, 1), occupantReach(cell).width() - 2);
    return tag;
}

QRect TileTag::occupantReach(const QRect& cell) {
    return {cell.topLeft(), QSize(OccupantTiles * cell.width(), cell.height())};
}

// The text, shortened to `room` pixels where it is wider, on a backing with its top left at `corner`.
void TileTag::place(const QString& name, QPoint corner, int room) {
    m_text = name;
    int advance = laidOut(name);
    if (advance + 4 > room) { // shortening lays the text out again: only where it is needed
        m_text = NameElision::shorten(name, QFontMetrics(m_font), room - 4);
        advance = laidOut(m_text);
    }
    glyphTable().font(m_font);
    m_rect = QRect(corner, QSize(advance + 4, glyphTable().lineHeight()));
}

// Places the text's glyphs once, straight from the font's tables: a repaint then only blits them. Names on
// a plan are short words in Latin script, which need no shaping (2,000 names: 2 ms instead of 12 ms).
// A character the font lacks falls back to Qt's text layout, which finds another font for it.
int TileTag::laidOut(const QString& text) {
    GlyphTable& table = glyphTable();
    const QRawFont& font = table.font(m_font);
    QList<quint32> glyphs;
    QList<QPointF> positions;
    glyphs.reserve(text.size());
    positions.reserve(text.size());
    QPointF pen(2, font.ascent());
    for (const QChar character : text) {
        const Glyph glyph = table.glyph(character);
        if (!font.isValid() || glyph.index == 0)
            return laidOutByQt(text);
        glyphs.append(glyph.index);
        positions.append(pen);
        pen += glyph.advance;
    }
    m_glyphs.setRawFont(font);
    m_glyphs.setGlyphIndexes(glyphs);
    m_glyphs.setPositions(positions);
    return int(std::ceil(pen.x() - 2));
}

// Qt's own text layout, which finds another font for a character the tags' font lacks.
int TileTag::laidOutByQt(const QString& text) {
    m_glyphs = QGlyphRun();
    m_shaped.emplace(text);
    m_shaped->setTextFormat(Qt::PlainText);
    m_shaped->prepare(QTransform(), m_font);
    return int(std::ceil(m_shaped->size().width()));
}

QFont TileTag::tagFont(const QFont& font, int tileSize) {
    QFont sized = font;
    sized.setPixelSize(std::clamp(tileSize * 3 / 10, ReadablePixels, 13));
    return sized;
}

void TileTag::paint(QPainter& painter, const TrackColors& colors) const {
    paintBacking(painter, colors);
    paintText(painter, colors);
}

void TileTag::paintBacking(QPainter& painter, const TrackColors& colors) const {
    if (!shown())
        return;
    QColor backing = m_occupant ? colors.occupied : colors.background;
    backing.setAlpha(m_occupant ? 255 : 215);
    painter.fillRect(m_rect, backing);
}

QColor TileTag::textColor(const TrackColors& colors) const {
    if (!m_occupant)
        return colors.text;
    return colors.occupied.lightness() < 150 ? QColor(Qt::white) : QColor(Qt::black);
}

void TileTag::paintText(QPainter& painter, const TrackColors& colors) const {
    if (!shown())
        return;
    painter.setPen(textColor(colors));
    if (!m_glyphs.isEmpty())
        painter.drawGlyphRun(m_rect.topLeft(), m_glyphs);
    else if (m_shaped)
        painter.drawStaticText(m_rect.topLeft() + QPoint(2, 0), *m_shaped);
}

TileTagBatch::TileTagBatch(const QFont& font) : m_font(font), m_fontDescription(font.toString()) {}

void TileTagBatch::add(const TileTag& tag) {
    if (!tag.shown())
        return;
    m_tags.push_back(&tag);
    if (tag.m_glyphs.isEmpty()) {
        m_shaped.push_back(&tag);
        return;
    }
    m_glyphIndexes.append(tag.m_glyphs.glyphIndexes());
    const QPointF corner = tag.m_rect.topLeft();
    for (const QPointF& position : tag.m_glyphs.positions())
        m_glyphPositions.append(position + corner);
}

void TileTagBatch::paintBackings(QPainter& painter, const TrackColors& colors, const QRect& area) const {
    for (const TileTag* tag : m_tags)
        if (tag->rect().intersects(area))
            tag->paintBacking(painter, colors);
}

// Every thread draws with a font of its own: Qt makes fonts per thread, a glyph cache must not be shared
// between threads, and a QFont's copies share the data that finds its font. The same font description
// gives the same glyph numbers on every thread.
void TileTagBatch::paintGlyphs(QPainter& painter, const TrackColors& colors) const {
    if (m_glyphIndexes.isEmpty())
        return;
    QFont own;
    own.fromString(m_fontDescription);
    QGlyphRun run;
    run.setRawFont(QRawFont::fromFont(own));
    run.setGlyphIndexes(m_glyphIndexes);
    run.setPositions(m_glyphPositions);
    painter.setPen(colors.text);
    painter.drawGlyphRun(QPointF(0, 0), run);
}

void TileTagBatch::paintShaped(QPainter& painter, const TrackColors& colors) const {
    painter.setFont(m_font);
    for (const TileTag* tag : m_shaped)
        tag->paintText(painter, colors);
}

} // namespace stellwerk::ui
