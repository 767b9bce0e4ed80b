#include "shell/ApplicationInfo.h"

namespace stellwerk::ui {

QString applicationVersion() {
    return QStringLiteral(STELLWERK_VERSION);
}

QIcon applicationIcon() {
    return QIcon(QStringLiteral(":/icons/stellwerk.svg"));
}

} // namespace stellwerk::ui
