#pragma once

#include "connection/LocomotivePictures.h"

#include <QHash>
#include <QObject>
#include <QPixmap>
#include <QPointer>
#include <QSize>
#include <QString>

namespace stellwerk::ui {

// The locomotives' pictures as the desk shows them: the connection's bytes decoded once and scaled to
// the place they fill, or a clean placeholder (a grey outline of a locomotive) while a picture is
// loading, when the station has none, or when its bytes do not decode. Every throttle, the loco list and
// the editor share one book, so a picture is fetched and decoded once.
class LocomotivePictureBook final : public QObject {
    Q_OBJECT

public:
    explicit LocomotivePictureBook(connection::LocomotivePictures* pictures, QObject* parent = nullptr);

    // The picture of the locomotive whose `.icon` is `icon`, fitted into `box` (logical pixels, for a
    // screen of this device pixel ratio), or the placeholder.
    QPixmap picture(const QString& icon, const QSize& box, qreal devicePixelRatio = 1.0);
    // True when picture() shows the locomotive's own picture, not the placeholder.
    bool hasPicture(const QString& icon);
    // What the picture is, in words, for a tooltip: "Picture “BR 218”", "No picture “BR 86”: ..." and,
    // on a second line, where it was looked for (the station's address, a file).
    QString describe(const QString& icon) const;

    // The placeholder alone, fitted into `box`.
    static QPixmap placeholder(const QSize& box, qreal devicePixelRatio = 1.0);

signals:
    // A picture arrived or was found missing: whoever shows one asks again.
    void changed();

private:
    const QImage* decoded(const QString& icon);
    static QString why(connection::LocomotivePictures::Reason reason);

    QPointer<connection::LocomotivePictures> m_pictures;
    QHash<QString, QImage> m_decoded; // by icon; a null image: the bytes did not decode
};

} // namespace stellwerk::ui
