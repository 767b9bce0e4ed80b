#pragma once

#include <QColor>
#include <QIcon>
#include <QString>
#include <initializer_list>
#include <utility>

class QAction;
class QWidget;

namespace stellwerk::ui {

// Our own toolbar drawings (resources/tool-icons, embedded as :/tool-icons/<name>.svg), painted in the
// palette's text colour so that a toolbar reads the same on light and dark palettes.
class ToolIcons final {
public:
    enum class Tool {
        OpenLayout,
        ExportLayout,
        StationPlan,
        ZoomIn,
        ZoomOut,
        Fit,
        Blocks,
        Connect,
        AddThrottle
    };

    static QString resourcePath(Tool tool);
    static QIcon icon(Tool tool, const QColor& color);
    // Gives `action` the tool's drawing in the colour of `widget`'s button text.
    static void apply(QAction* action, Tool tool, const QWidget& widget);
    static void apply(const QWidget& widget, std::initializer_list<std::pair<QAction*, Tool>> actions);
    // A black SVG drawing `size` pixels square in `color`; null when it cannot be read.
    static QIcon tinted(const QString& path, const QColor& color, int size);
};

} // namespace stellwerk::ui
