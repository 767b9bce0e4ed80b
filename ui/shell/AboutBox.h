#pragma once

#include <QCoreApplication>
#include <QString>

class QWidget;

namespace stellwerk::ui {

// Help → About Stellwerk: the version, one sentence on what Stellwerk is, and the Qt it runs on.
class AboutBox final {
    Q_DECLARE_TR_FUNCTIONS(AboutBox)

public:
    static QString title();
    static QString text();
    static void show(QWidget* parent);
};

} // namespace stellwerk::ui
