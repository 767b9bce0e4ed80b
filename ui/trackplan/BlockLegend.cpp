#include "trackplan/BlockLegend.h"

#include "trackplan/TrackColors.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>

namespace stellwerk::ui {
namespace {

constexpr QSize SwatchSize(28, 14);

} // namespace

BlockLegend::BlockLegend(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("blockLegend"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 2, 8, 2);
    layout->setSpacing(6);
    m_title = new QLabel(this);
    m_title->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(m_title);
    for (const BlockShade shade : {BlockShade::Free, BlockShade::Reserved, BlockShade::Occupied,
                                   BlockShade::Ghost, BlockShade::Fault}) {
        auto* swatch = new QLabel(this);
        auto* text = new QLabel(this);
        layout->addSpacing(6);
        layout->addWidget(swatch);
        layout->addWidget(text);
        m_entries.push_back({shade, swatch, text});
    }
    layout->addStretch(1);
    redraw();
    retranslate();
}

QStringList BlockLegend::texts() const {
    QStringList texts;
    for (const Entry& entry : m_entries)
        texts << entry.text->text();
    return texts;
}

// Each shade as the plan draws a block: the band on the plan's background inside its edge.
void BlockLegend::redraw() {
    const TrackColors colors = TrackColors::from(palette());
    const qreal ratio = devicePixelRatioF();
    for (const Entry& entry : m_entries) {
        const BlockShadeLook look = BlockShadeLook::of(entry.shade, colors);
        QPixmap swatch(SwatchSize * ratio);
        swatch.setDevicePixelRatio(ratio);
        swatch.fill(colors.background);
        QPainter painter(&swatch);
        const QRect box(QPoint(0, 0), SwatchSize);
        painter.fillRect(box, look.edge);
        painter.fillRect(box.adjusted(2, 2, -2, -2), colors.background);
        painter.fillRect(box.adjusted(2, 2, -2, -2), look.band);
        painter.end();
        entry.swatch->setPixmap(swatch);
    }
}

// Short words, so that the line fits a narrow window; the pattern is in the swatch, the sentence in the
// tooltip.
void BlockLegend::retranslate() {
    m_title->setText(tr("Blocks:"));
    for (const Entry& entry : m_entries)
        switch (entry.shade) {
        case BlockShade::Free:
            entry.text->setText(tr("free"));
            break;
        case BlockShade::Reserved:
            entry.text->setText(tr("reserved"));
            break;
        case BlockShade::Occupied:
            entry.text->setText(tr("train in it"));
            break;
        case BlockShade::Ghost:
            entry.text->setText(tr("unknown occupant"));
            break;
        case BlockShade::Fault:
            entry.text->setText(tr("fault"));
            break;
        case BlockShade::Plain:
            break;
        }
    setToolTip(
        tr("A train's blocks are solid and named with it; the blocks and turnouts reserved for its way "
           "hatched; a block occupied by something no train can have reached cross-hatched; a train "
           "stopped by a fault dotted. Free blocks are outlined while \"Blocks\" is on."));
}

void BlockLegend::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    if (event->type() == QEvent::PaletteChange)
        redraw();
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
