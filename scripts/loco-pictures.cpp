// Draws the demo layout's locomotive pictures (resources/demo-layout/icons/<icon>.png): simple side
// views in the railways' colours, 240x80 like a station's loco icons. Run scripts/loco-pictures.sh.
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QString>
#include <cstdio>

namespace {

enum class Shape { Steam, Tank, Diesel, Hood, Electric, Express, Railbus, Shunter };

struct Picture {
    const char* icon;
    Shape shape;
    QColor body;
    QColor stripe;
};

constexpr int Width = 240;
constexpr int Height = 80;
constexpr double Rail = 70;

void wheel(QPainter& p, double x, double r, const QColor& rim) {
    p.setPen(QPen(QColor(30, 30, 30), 2));
    p.setBrush(rim);
    p.drawEllipse(QPointF(x, Rail - r), r, r);
    p.setBrush(QColor(60, 60, 60));
    p.drawEllipse(QPointF(x, Rail - r), r * 0.35, r * 0.35);
}

void bogie(QPainter& p, double centre, int axles) {
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(45, 45, 45));
    p.drawRect(QRectF(centre - 9.0 * axles, Rail - 15, 18.0 * axles, 6));
    for (int i = 0; i < axles; ++i)
        wheel(p, centre - 9.0 * (axles - 1) + 18.0 * i, 7, QColor(70, 70, 70));
}

void windows(QPainter& p, double left, double right, double top, double height, double step) {
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(190, 215, 235));
    for (double x = left; x + step * 0.6 <= right; x += step)
        p.drawRoundedRect(QRectF(x, top, step * 0.6, height), 2, 2);
}

void pantograph(QPainter& p, double x, double roof) {
    p.setPen(QPen(QColor(40, 40, 40), 2));
    p.drawLine(QPointF(x - 10, roof), QPointF(x, roof - 10));
    p.drawLine(QPointF(x, roof - 10), QPointF(x + 8, roof - 14));
    p.drawLine(QPointF(x - 4, roof - 14), QPointF(x + 16, roof - 14));
}

QPainterPath cab(double left, double right, double top, double bottom, double nose) {
    QPainterPath path;
    path.moveTo(left + nose, top);
    path.lineTo(right - nose, top);
    path.quadTo(right, top, right, top + nose);
    path.lineTo(right, bottom);
    path.lineTo(left, bottom);
    path.lineTo(left, top + nose);
    path.quadTo(left, top, left + nose, top);
    return path;
}

void electric(QPainter& p, const Picture& picture, double nose) {
    p.setPen(QPen(picture.body.darker(150), 1.5));
    p.setBrush(picture.body);
    p.drawPath(cab(24, 216, 22, 56, nose));
    p.setPen(Qt::NoPen);
    p.setBrush(picture.stripe);
    p.drawRect(QRectF(26, 48, 188, 4));
    windows(p, 30, 48, 27, 11, 18);
    windows(p, 196, 212, 27, 11, 18);
    windows(p, 70, 180, 30, 8, 16);
    pantograph(p, 80, 22);
    pantograph(p, 160, 22);
    bogie(p, 68, 2);
    bogie(p, 172, 2);
}

void diesel(QPainter& p, const Picture& picture) {
    p.setPen(QPen(picture.body.darker(150), 1.5));
    p.setBrush(picture.body);
    p.drawPath(cab(30, 210, 26, 56, 6));
    p.setBrush(picture.stripe);
    p.drawRect(QRectF(30, 50, 180, 6));
    windows(p, 100, 140, 30, 12, 20);
    p.setPen(QPen(picture.body.darker(170), 1));
    for (double x = 44; x < 96; x += 8)
        p.drawLine(QPointF(x, 32), QPointF(x, 46));
    for (double x = 150; x < 200; x += 8)
        p.drawLine(QPointF(x, 32), QPointF(x, 46));
    bogie(p, 66, 2);
    bogie(p, 174, 2);
}

void hood(QPainter& p, const Picture& picture, bool shunter) {
    const double right = shunter ? 170 : 206;
    p.setPen(QPen(picture.body.darker(150), 1.5));
    p.setBrush(picture.body);
    p.drawRoundedRect(QRectF(40, 34, right - 40, 20), 4, 4);
    p.drawRoundedRect(QRectF(shunter ? 120 : 100, 20, 40, 34), 3, 3);
    windows(p, shunter ? 124 : 104, shunter ? 158 : 138, 25, 11, 17);
    p.setPen(Qt::NoPen);
    p.setBrush(picture.stripe);
    p.drawRect(QRectF(40, 52, right - 40, 4));
    if (shunter) {
        wheel(p, 80, 9, QColor(70, 70, 70));
        wheel(p, 140, 9, QColor(70, 70, 70));
    } else {
        bogie(p, 72, 2);
        bogie(p, 176, 2);
    }
}

void express(QPainter& p, const Picture& picture) {
    QPainterPath body;
    body.moveTo(4, 56);
    body.cubicTo(10, 30, 40, 24, 70, 24);
    body.lineTo(236, 24);
    body.lineTo(236, 56);
    body.closeSubpath();
    p.setPen(QPen(QColor(150, 150, 150), 1.5));
    p.setBrush(picture.body);
    p.drawPath(body);
    p.setPen(Qt::NoPen);
    p.setBrush(picture.stripe);
    p.drawRect(QRectF(40, 49, 196, 4));
    p.setBrush(QColor(40, 50, 60));
    p.drawRect(QRectF(70, 31, 166, 9));
    p.drawPolygon(QPolygonF({QPointF(30, 36), QPointF(62, 28), QPointF(62, 38)}));
    bogie(p, 80, 2);
    bogie(p, 200, 2);
}

void railbus(QPainter& p, const Picture& picture) {
    p.setPen(QPen(picture.body.darker(150), 1.5));
    p.setBrush(picture.stripe);
    p.drawPath(cab(20, 220, 20, 56, 12));
    p.setPen(Qt::NoPen);
    p.setBrush(picture.body);
    p.drawRect(QRectF(20, 42, 200, 14));
    windows(p, 30, 212, 26, 12, 18);
    wheel(p, 70, 8, QColor(70, 70, 70));
    wheel(p, 170, 8, QColor(70, 70, 70));
}

void steam(QPainter& p, const Picture& picture, bool tank) {
    const QColor black(35, 35, 35);
    p.setPen(QPen(QColor(10, 10, 10), 1.5));
    p.setBrush(black);
    p.drawRoundedRect(QRectF(24, 30, 120, 24), 10, 10); // boiler
    p.drawRect(QRectF(34, 16, 10, 16));                 // chimney
    p.drawRoundedRect(QRectF(84, 22, 16, 10), 5, 5);    // dome
    p.drawRect(QRectF(136, 18, 34, 38));                // cab
    if (!tank)
        p.drawRect(QRectF(176, 28, 56, 28)); // tender
    windows(p, 144, 166, 23, 10, 20);
    p.setPen(Qt::NoPen);
    p.setBrush(picture.stripe);
    p.drawRect(QRectF(20, 54, tank ? 152 : 214, 3));
    const QColor rim = picture.body;
    const int drivers = tank ? 4 : 3;
    for (int i = 0; i < drivers; ++i)
        wheel(p, 60 + 24.0 * i, 11, rim);
    wheel(p, 34, 6, rim);
    if (!tank) {
        wheel(p, 190, 6, rim);
        wheel(p, 218, 6, rim);
    }
    p.setPen(QPen(QColor(180, 180, 180), 2));
    p.drawLine(QPointF(60, 59), QPointF(60 + 24.0 * (drivers - 1), 59));
}

void rail(QPainter& p) {
    p.setPen(QPen(QColor(110, 110, 110), 3));
    p.drawLine(QPointF(0, Rail + 2), QPointF(Width, Rail + 2));
}

QImage draw(const Picture& picture) {
    QImage image(Width, Height, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    rail(p);
    switch (picture.shape) {
    case Shape::Steam:
    case Shape::Tank:
        steam(p, picture, picture.shape == Shape::Tank);
        break;
    case Shape::Diesel:
        diesel(p, picture);
        break;
    case Shape::Hood:
    case Shape::Shunter:
        hood(p, picture, picture.shape == Shape::Shunter);
        break;
    case Shape::Electric:
        electric(p, picture, 8);
        break;
    case Shape::Express:
        express(p, picture);
        break;
    case Shape::Railbus:
        railbus(p, picture);
        break;
    }
    return image;
}

} // namespace

int main(int argc, char** argv) {
    QGuiApplication app(argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: loco-pictures DIRECTORY\n");
        return 2;
    }
    const QColor dbRed(179, 38, 30);
    const QColor cream(236, 226, 196);
    const Picture pictures[] = {
        {"BR 218", Shape::Diesel, dbRed, QColor(60, 60, 60)},
        {"V 100", Shape::Hood, dbRed, QColor(60, 60, 60)},
        {"ICE 3", Shape::Express, QColor(245, 245, 245), QColor(200, 20, 30)},
        {"Koef III", Shape::Shunter, dbRed, QColor(230, 190, 40)},
        {"BR 01", Shape::Steam, QColor(190, 30, 30), QColor(190, 30, 30)},
        {"E 44", Shape::Electric, QColor(40, 90, 60), QColor(60, 60, 60)},
        {"BR 212", Shape::Hood, dbRed, cream},
        {"Taurus", Shape::Electric, QColor(200, 20, 30), QColor(240, 240, 240)},
        {"BR 89", Shape::Tank, QColor(190, 30, 30), QColor(190, 30, 30)},
        {"VT 98", Shape::Railbus, dbRed, cream},
        {"Re 460", Shape::Electric, QColor(210, 25, 25), QColor(250, 250, 250)},
        {"BR 103", Shape::Electric, dbRed, cream},
    };
    for (const Picture& picture : pictures) {
        const QString file = QString::fromUtf8(argv[1]) + '/' + QString::fromUtf8(picture.icon) + ".png";
        if (!draw(picture).save(file, "PNG")) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(file));
            return 1;
        }
    }
    return 0;
}
