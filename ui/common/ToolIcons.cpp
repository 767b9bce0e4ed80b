#include "common/ToolIcons.h"

#include <QAction>
#include <QImageReader>
#include <QPainter>
#include <QPixmap>
#include <QWidget>

namespace stellwerk::ui {
namespace {

constexpr int DrawnSize = 48; // twice the toolbar's icon size: sharp on a high-density screen too

} // namespace

QString ToolIcons::resourcePath(Tool tool) {
    switch (tool) {
    case Tool::OpenLayout:
        return QStringLiteral(":/tool-icons/open-layout.svg");
    case Tool::ExportLayout:
        return QStringLiteral(":/tool-icons/export-layout.svg");
    case Tool::StationPlan:
        return QStringLiteral(":/tool-icons/station-plan.svg");
    case Tool::ZoomIn:
        return QStringLiteral(":/tool-icons/zoom-in.svg");
    case Tool::ZoomOut:
        return QStringLiteral(":/tool-icons/zoom-out.svg");
    case Tool::Fit:
        return QStringLiteral(":/tool-icons/fit.svg");
    case Tool::Blocks:
        return QStringLiteral(":/tool-icons/blocks.svg");
    case Tool::Connect:
        return QStringLiteral(":/tool-icons/connect.svg");
    case Tool::AddThrottle:
        return QStringLiteral(":/tool-icons/add-throttle.svg");
    }
    return {};
}

QIcon ToolIcons::icon(Tool tool, const QColor& color) {
    return tinted(resourcePath(tool), color, DrawnSize);
}

void ToolIcons::apply(QAction* action, Tool tool, const QWidget& widget) {
    action->setIcon(icon(tool, widget.palette().color(QPalette::ButtonText)));
}

void ToolIcons::apply(const QWidget& widget, std::initializer_list<std::pair<QAction*, Tool>> actions) {
    for (const auto& [action, tool] : actions)
        apply(action, tool, widget);
}

QIcon ToolIcons::tinted(const QString& path, const QColor& color, int size) {
    // Read through Qt's SVG image plugin (libqt6svg6, which the application icon needs as well).
    QImageReader reader(path);
    reader.setScaledSize(QSize(size, size));
    QImage image = reader.read();
    if (image.isNull())
        return {};
    image = image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    painter.setCompositionMode(QPainter::CompositionMode_SourceIn);
    painter.fillRect(image.rect(), color);
    painter.end();
    return QIcon(QPixmap::fromImage(image));
}

} // namespace stellwerk::ui
