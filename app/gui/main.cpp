// Start-up of the Stellwerk desktop application: language from the settings, then the main window.

#include "ApplicationInfo.h"
#include "FrameDecoderPanel.h"
#include "LanguageSettings.h"
#include "MainWindow.h"
#include "Translations.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QPixmap>
#include <QTimer>
#include <cstdio>

namespace {

struct Options {
    QString screenshotFile; // empty: run normally
    QString captureFile;    // a capture to open in the frame decoder
};

Options parseOptions(const QApplication& app) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Desktop control station for Märklin CS2/CS3 model railways"));
    parser.addHelpOption();
    parser.addVersionOption();
    QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                  QStringLiteral("Save a picture of the main window to <file> and quit."),
                                  QStringLiteral("file"));
    screenshot.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(screenshot);
    QCommandLineOption decode(QStringLiteral("decode"),
                              QStringLiteral("Open a CAN capture (candump log, can2udp log, frames in the "
                                             "document's notation) in the frame decoder."),
                              QStringLiteral("file"));
    parser.addOption(decode);
    parser.process(app);
    return Options{parser.value(screenshot), parser.value(decode)};
}

// For documentation: grabs the shown window once the event loop runs, then ends with 0 or 1.
void saveScreenshotAndQuit(QWidget& window, const QString& file) {
    QTimer::singleShot(200, &window, [&window, file] {
        if (window.grab().save(file)) {
            QCoreApplication::exit(0);
            return;
        }
        std::fprintf(stderr, "stellwerk: cannot write the screenshot to %s\n", qPrintable(file));
        QCoreApplication::exit(1);
    });
}

} // namespace

int main(int argc, char* argv[]) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Stellwerk"));
    QApplication::setApplicationName(QStringLiteral("Stellwerk"));
    QApplication::setApplicationVersion(stellwerk::ui::applicationVersion());
    QApplication::setWindowIcon(stellwerk::ui::applicationIcon());
    const Options options = parseOptions(app);

    stellwerk::ui::Translations translations;
    translations.select(stellwerk::ui::LanguageSettings::load());
    stellwerk::ui::MainWindow window(translations);
    if (!options.captureFile.isEmpty()) {
        if (const QString error = window.frameDecoder()->loadCapture(options.captureFile); !error.isEmpty()) {
            std::fprintf(stderr, "stellwerk: %s\n", qPrintable(error));
            return 1;
        }
    }
    window.show();
    if (!options.screenshotFile.isEmpty()) {
        saveScreenshotAndQuit(window, options.screenshotFile);
    }
    return QApplication::exec();
}
