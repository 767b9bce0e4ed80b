#pragma once

#include <QIcon>
#include <QString>

namespace stellwerk::ui {

// Facts about the program itself, shared by main(), the main window and the about box.
QString applicationVersion(); // PROJECT_VERSION of the build, e.g. "0.1.0"
QIcon applicationIcon();      // the signal icon from resources/stellwerk.svg

} // namespace stellwerk::ui
