#include "common/StatusDot.h"

#include <QPainter>
#include <QPixmap>

namespace stellwerk::ui::StatusDot {

QIcon icon(const QColor& colour, int size) {
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(colour.darker(140));
    painter.setBrush(colour);
    painter.drawEllipse(QRectF(1, 1, size - 2, size - 2));
    return QIcon(pixmap);
}

} // namespace stellwerk::ui::StatusDot
