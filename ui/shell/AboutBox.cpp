#include "shell/AboutBox.h"

#include "shell/ApplicationInfo.h"

#include <QMessageBox>

namespace stellwerk::ui {

QString AboutBox::title() {
    return tr("About Stellwerk");
}

QString AboutBox::text() {
    const QString heading = QStringLiteral("<h3>Stellwerk %1</h3>").arg(applicationVersion());
    const QString purpose = tr("Stellwerk is a desktop control station for Märklin digital model railways "
                               "that speaks the CAN protocol of the Central Station 2 and 3.");
    const QString qt =
        tr("Built with Qt %1, running on Qt %2.").arg(QStringLiteral(QT_VERSION_STR), qVersion());
    return heading + QStringLiteral("<p>%1</p><p>%2</p>").arg(purpose.toHtmlEscaped(), qt.toHtmlEscaped());
}

void AboutBox::show(QWidget* parent) {
    QMessageBox::about(parent, title(), text());
}

} // namespace stellwerk::ui
