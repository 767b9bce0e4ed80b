#include "throttle/StyleSheetSupport.h"

#include <QStyle>
#include <QWidget>

namespace stellwerk::ui {

void repolish(QWidget* widget) {
    widget->style()->unpolish(widget);
    widget->style()->polish(widget);
    widget->updateGeometry(); // a rule with a border or padding asks for another size
}

void restyle(QWidget* widget, const QString& sheet) {
    static bool restyling = false;
    if (restyling)
        return;
    restyling = true;
    widget->setStyleSheet(QString());
    widget->setStyleSheet(sheet);
    restyling = false;
}

} // namespace stellwerk::ui
