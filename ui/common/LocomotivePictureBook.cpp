#include "common/LocomotivePictureBook.h"

#include "connection/LocomotivePictures.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QPalette>
#include <QUrl>

namespace stellwerk::ui {

using Status = connection::LocomotivePictures::Status;

namespace {

QSize devicePixels(const QSize& box, qreal ratio) {
    return (QSizeF(box) * ratio).toSize().expandedTo(QSize(1, 1));
}

// A side view of a locomotive in the palette's quiet colours, 3:1 like the stations' pictures.
void drawOutline(QPainter& painter, const QRectF& area, const QPalette& palette) {
    const qreal unit = std::min(area.width() / 30.0, area.height() / 10.0);
    const QPointF origin(area.center().x() - 15 * unit, area.center().y() - 5 * unit);
    auto at = [&](qreal x, qreal y) { return origin + QPointF(x * unit, y * unit); };
    QPainterPath body;
    body.addRoundedRect(QRectF(at(3, 3), at(27, 7.5)), unit, unit);
    body.addRoundedRect(QRectF(at(18, 1.2), at(25, 3.2)), unit * 0.5, unit * 0.5);
    QColor shade = palette.color(QPalette::Mid);
    painter.setPen(Qt::NoPen);
    painter.setBrush(shade);
    painter.drawPath(body.simplified());
    for (const qreal x : {7.0, 11.0, 19.0, 23.0})
        painter.drawEllipse(at(x, 8.2), unit * 1.1, unit * 1.1);
    painter.setPen(QPen(shade, std::max<qreal>(1.0, unit * 0.4)));
    painter.drawLine(at(0.5, 9.6), at(29.5, 9.6));
}

} // namespace

LocomotivePictureBook::LocomotivePictureBook(connection::LocomotivePictures* pictures, QObject* parent)
    : QObject(parent), m_pictures(pictures) {
    if (m_pictures)
        connect(m_pictures, &connection::LocomotivePictures::picturesChanged, this, [this] {
            m_decoded.clear();
            emit changed();
        });
}

const QImage* LocomotivePictureBook::decoded(const QString& icon) {
    if (!m_pictures)
        return nullptr;
    if (const auto found = m_decoded.constFind(icon); found != m_decoded.constEnd())
        return found->isNull() ? nullptr : &*found;
    const std::optional<QByteArray> bytes = m_pictures->picture(icon);
    if (!bytes)
        return nullptr; // not there (yet): asked again on changed()
    const QImage image = QImage::fromData(*bytes, "PNG");
    const auto stored = m_decoded.insert(icon, image);
    return image.isNull() ? nullptr : &*stored;
}

bool LocomotivePictureBook::hasPicture(const QString& icon) {
    return decoded(icon) != nullptr;
}

QPixmap LocomotivePictureBook::picture(const QString& icon, const QSize& box, qreal devicePixelRatio) {
    const QImage* image = decoded(icon);
    if (!image)
        return placeholder(box, devicePixelRatio);
    QPixmap pixmap = QPixmap::fromImage(
        image->scaled(devicePixels(box, devicePixelRatio), Qt::KeepAspectRatio, Qt::SmoothTransformation));
    pixmap.setDevicePixelRatio(devicePixelRatio);
    return pixmap;
}

QPixmap LocomotivePictureBook::placeholder(const QSize& box, qreal devicePixelRatio) {
    const QSize size = devicePixels(box, devicePixelRatio);
    QPixmap pixmap(size);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    drawOutline(painter, QRectF(QPointF(0, 0), QSizeF(size)), QApplication::palette());
    painter.end();
    pixmap.setDevicePixelRatio(devicePixelRatio);
    return pixmap;
}

QString LocomotivePictureBook::describe(const QString& icon) const {
    if (!m_pictures)
        return tr("No picture: no station");
    if (icon.isEmpty())
        return tr("This locomotive names no picture");
    switch (m_pictures->status(icon)) {
    case Status::Present:
        return m_decoded.contains(icon) && m_decoded.value(icon).isNull()
                   ? tr("The picture “%1” is damaged").arg(icon)
                   : tr("Picture “%1”").arg(icon);
    case Status::Unknown:
    case Status::Loading:
        return tr("Loading the picture “%1”…").arg(icon);
    case Status::Missing:
    case Status::Failed:
        break;
    }
    const QString missing = tr("No picture “%1”: %2").arg(icon, why(m_pictures->reason(icon)));
    const QString where = m_pictures->lookedAt(icon);
    if (where.isEmpty())
        return missing;
    const QUrl url(where);
    const QString place = url.scheme().startsWith(QLatin1String("http")) ? url.toDisplayString()
                                                                         : QDir::toNativeSeparators(where);
    return missing + QLatin1Char('\n') + tr("Looked for at %1").arg(place);
}

QString LocomotivePictureBook::why(connection::LocomotivePictures::Reason reason) {
    using Reason = connection::LocomotivePictures::Reason;
    switch (reason) {
    case Reason::NoName:
        return tr("not a usable file name");
    case Reason::NoSource:
        return tr("no station to ask and no icons folder");
    case Reason::NotThere:
        return tr("the station has none");
    case Reason::NotAPicture:
        return tr("the file is not a usable PNG picture");
    case Reason::Unreachable:
        return tr("the station did not send it; asked again when it is back");
    case Reason::None:
        break;
    }
    return tr("not known yet");
}

} // namespace stellwerk::ui
