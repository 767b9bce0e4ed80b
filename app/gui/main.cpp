// Start-up of the Stellwerk desktop application: language from the settings, then the main window, then the
// station (the one in the settings or on the command line; the embedded simulated one when none is set).

#include "binding/RailwayBinding.h"
#include "connect/StationUrlSettings.h"
#include "connection/StationConnection.h"
#include "mcanhandhelds/HandheldBook.h"
#include "model/LayoutInUse.h"
#include "model/OccupantBook.h"
#include "model/Railway.h"
#include "monitor/FrameDecoderPanel.h"
#include "operation/Operation.h"
#include "phones/PhoneServers.h"
#include "shell/ApplicationInfo.h"
#include "shell/LanguageSettings.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "shell/Workspace.h"
#include "sim/EmbeddedStation.h"
#include "trackplan/TrackPlanPanel.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QPixmap>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <cstdio>
#include <functional>
#include <optional>

namespace {

using stellwerk::connection::StationConnection;

// How long a screenshot waits for the station to be ready before it shows whatever state it reached.
constexpr int ScreenshotPatienceMs = 15000;
// How long it waits for texts to be laid out, and, once the station is ready, for trains to move.
constexpr int SettleMs = 200;
constexpr int LivelyMs = 1500;

struct Options {
    QString screenshotFile;      // empty: run normally
    QString captureFile;         // a capture to open in the frame decoder
    QString stationUrl;          // the station to connect to; empty: the embedded simulated station
    QString panel;               // object name of the panel to bring to the front (for screenshots)
    QSize size;                  // the window's size (for screenshots); empty: as remembered
    bool reportGeometry = false; // print where the window and its status bar are on the screen, and quit
    QStringList furtherBuses;    // more buses to hold open beside the station's
    std::optional<QString> z21;  // --z21 [HOST:]PORT: the Z21 server on for this run
    std::optional<QString> withrottle; // --withrottle [HOST:]PORT: the WiThrottle server on for this run
};

QString rectText(const QRect& rect) {
    return QStringLiteral("%1,%2 %3x%4").arg(rect.x()).arg(rect.y()).arg(rect.width()).arg(rect.height());
}

// The panels in front of their docks that scroll sideways, because their docks are narrower than they need.
int panelsScrollingSideways(const stellwerk::ui::MainWindow& window) {
    int count = 0;
    for (const QDockWidget* dock : window.workspace()->docks()) {
        const QWidget* panel = stellwerk::ui::Workspace::panelOf(dock);
        const auto* scroll = qobject_cast<const QScrollArea*>(dock->widget());
        count += panel && scroll && panel->isVisible() && scroll->horizontalScrollBar()->isVisible() ? 1 : 0;
    }
    return count;
}

// For the first-start test under a window manager: the screen's free area, the window with and without
// its frame, the status bar (all in screen pixels), the plan's zoom and the panels that scroll sideways.
void reportGeometry(const stellwerk::ui::MainWindow& window) {
    const QRect statusBar(window.statusBar()->mapToGlobal(QPoint()), window.statusBar()->size());
    std::printf("available %s\nframe %s\nwindow %s\nstatus bar %s\nplan tile %d\nscrolling sideways %d\n",
                qPrintable(rectText(window.screen()->availableGeometry())),
                qPrintable(rectText(window.frameGeometry())), qPrintable(rectText(window.geometry())),
                qPrintable(rectText(statusBar)), window.trackPlan()->tileSize(),
                panelsScrollingSideways(window));
    std::fflush(stdout);
}

// --simulated wins over --station, which wins over the settings.
QString stationUrl(const QCommandLineParser& parser, const QCommandLineOption& station,
                   const QCommandLineOption& simulated) {
    if (parser.isSet(simulated))
        return QString();
    if (parser.isSet(station))
        return parser.value(station);
    return stellwerk::ui::StationUrlSettings::load();
}

// --size 1366x768; an empty size when not given or not readable.
QSize windowSize(const QString& text) {
    const QStringList parts = text.split(QLatin1Char('x'));
    if (parts.size() != 2)
        return {};
    return QSize(parts[0].toInt(), parts[1].toInt()).expandedTo(QSize(0, 0));
}

// --help and --version print text and end before any window exists: they need no display.
bool asksOnlyForText(int argc, char* argv[]) {
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        if (arg == "-h" || arg == "--help" || arg == "--help-all" || arg == "-?" || arg == "-v" ||
            arg == "--version")
            return true;
    }
    return false;
}

// A new embedded simulated station, telling `occupants` where its trains stand.
std::unique_ptr<stellwerk::transport::LocalPeer> embeddedStation(stellwerk::model::OccupantBook& occupants) {
    occupants.clear(); // a new simulation places its trains anew
    auto station = std::make_unique<stellwerk::sim::EmbeddedStation>();
    station->reportOccupants([&occupants](std::uint16_t device, std::uint16_t contact, std::uint32_t locId) {
        occupants.report(stellwerk::model::contactKey(device, contact), locId);
    });
    return station;
}

void nameApplication() {
    QCoreApplication::setOrganizationName(QStringLiteral("Stellwerk"));
    QCoreApplication::setApplicationName(QStringLiteral("Stellwerk"));
    QCoreApplication::setApplicationVersion(stellwerk::ui::applicationVersion());
}

Options parseOptions(const QCoreApplication& app) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Desktop control station for Märklin CS2/CS3 model railways"));
    parser.addHelpOption();
    parser.addVersionOption();
    QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                  QStringLiteral("Save a picture of the main window to <file> once the "
                                                 "station is ready, and quit (for documentation)."),
                                  QStringLiteral("file"));
    parser.addOption(screenshot);
    QCommandLineOption size(
        QStringLiteral("size"),
        QStringLiteral("Open the main window <width>x<height> pixels large, e.g. 1366x768 "
                       "(for screenshots)."),
        QStringLiteral("size"));
    parser.addOption(size);
    QCommandLineOption decode(QStringLiteral("decode"),
                              QStringLiteral("Open a CAN capture (candump log, can2udp log, frames in the "
                                             "document's notation) in the frame decoder."),
                              QStringLiteral("file"));
    parser.addOption(decode);
    QCommandLineOption station(QStringLiteral("station"),
                               QStringLiteral("Connect to the station at <url> (udp://192.168.2.5, "
                                              "tcp://192.168.2.5, can://socketcan/can0) instead of the one "
                                              "in the settings, without changing them."),
                               QStringLiteral("url"));
    parser.addOption(station);
    QCommandLineOption simulated(QStringLiteral("simulated"),
                                 QStringLiteral("Connect to the embedded simulated station (demo layout)."));
    parser.addOption(simulated);
    QCommandLineOption bus(QStringLiteral("bus"),
                           QStringLiteral("Also watch the CAN bus at <url> (can://socketcan/can1, a USB-CAN "
                                          "adapter wired to modules) beside the station; may be given more "
                                          "than once; replaces the further buses in the settings."),
                           QStringLiteral("url"));
    parser.addOption(bus);
    QCommandLineOption panel(QStringLiteral("panel"),
                             QStringLiteral("Bring a panel to the front first (its object name: statusPanel, "
                                            "busMonitorPanel, throttlePanel, ...)."),
                             QStringLiteral("name"));
    parser.addOption(panel);
    QCommandLineOption z21(QStringLiteral("z21"),
                           QStringLiteral("Run the Z21 server for the Z21 app and WLANmaus on [HOST:]PORT "
                                          "(21105: every interface) for this run, without changing the "
                                          "settings."),
                           QStringLiteral("[host:]port"));
    parser.addOption(z21);
    QCommandLineOption withrottle(QStringLiteral("withrottle"),
                                  QStringLiteral("Run the WiThrottle server for Engine Driver and WiThrottle "
                                                 "on [HOST:]PORT (12090: every interface) for this run."),
                                  QStringLiteral("[host:]port"));
    parser.addOption(withrottle);
    QCommandLineOption geometry(
        QStringLiteral("report-geometry"),
        QStringLiteral("Print where the window, its frame and its status bar are on the "
                       "screen once the station is ready, and quit (for tests)."));
    geometry.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(geometry);
    parser.process(app);
    return Options{parser.value(screenshot),
                   parser.value(decode),
                   stationUrl(parser, station, simulated),
                   parser.value(panel),
                   windowSize(parser.value(size)),
                   parser.isSet(geometry),
                   parser.isSet(bus) ? parser.values(bus) : stellwerk::ui::StationUrlSettings::furtherBuses(),
                   parser.isSet(z21) ? std::optional(parser.value(z21)) : std::nullopt,
                   parser.isSet(withrottle) ? std::optional(parser.value(withrottle)) : std::nullopt};
}

void grabAndQuit(QWidget& window, const QString& file) {
    if (window.grab().save(file)) {
        QCoreApplication::exit(0);
        return;
    }
    std::fprintf(stderr, "stellwerk: cannot write the screenshot to %s\n", qPrintable(file));
    QCoreApplication::exit(1);
}

bool settled(StationConnection::State state) {
    return state != StationConnection::State::Connecting &&
           state != StationConnection::State::LoadingConfiguration;
}

// Calls `then` `readyMs` after the station is ready (or a moment after it failed, or did not get there
// in time, so that the status bar can lay out its new text).
void whenSettled(QWidget& window, const StationConnection& connection, int readyMs,
                 const std::function<void()>& then) {
    auto* patience = new QTimer(&window);
    patience->setSingleShot(true);
    const auto thenIn = [&window, then, patience](int delayMs) {
        patience->stop();
        QTimer::singleShot(delayMs, &window, then);
    };
    QObject::connect(patience, &QTimer::timeout, &window, [thenIn] { thenIn(SettleMs); });
    QObject::connect(&connection, &StationConnection::stateChanged, patience,
                     [thenIn, patience, readyMs](StationConnection::State state) {
                         if (patience->isActive() && settled(state))
                             thenIn(state == StationConnection::State::Ready ? readyMs : SettleMs);
                     });
    patience->start(ScreenshotPatienceMs);
}

// For documentation: grabs the shown window once the demo's trains have moved, so that the layout shows
// occupied contacts and their times; for tests: reports the window's geometry first. Then ends with 0 or 1.
void reportAndQuit(stellwerk::ui::MainWindow& window, const StationConnection& connection,
                   const Options& options) {
    const QString file = options.screenshotFile;
    const bool report = options.reportGeometry;
    whenSettled(window, connection, file.isEmpty() ? SettleMs : LivelyMs, [&window, file, report] {
        if (report)
            reportGeometry(window);
        if (file.isEmpty())
            QCoreApplication::exit(0);
        else
            grabAndQuit(window, file);
    });
}

// The phone servers as saved, with --z21 and --withrottle switching theirs on for this run; nullopt (and
// the reason printed) when a flag cannot be read.
std::optional<stellwerk::phones::PhoneSettings> phoneSettings(QSettings& settings, const Options& options) {
    using stellwerk::phones::ListenAddress;
    using stellwerk::phones::PhoneSettings;
    PhoneSettings chosen = PhoneSettings::load(settings);
    const auto flag = [](const std::optional<QString>& text, quint16 port, bool& on, ListenAddress& listen) {
        if (!text)
            return true;
        const auto read = ListenAddress::parse(*text, port);
        on = on || read.has_value();
        listen = read.value_or(listen);
        return read.has_value();
    };
    if (!flag(options.z21, PhoneSettings::Z21Port, chosen.z21, chosen.z21Listen)) {
        std::fprintf(stderr, "stellwerk: --z21: expected [HOST:]PORT\n");
        return std::nullopt;
    }
    if (!flag(options.withrottle, PhoneSettings::WiThrottlePort, chosen.withrottle,
              chosen.withrottleListen)) {
        std::fprintf(stderr, "stellwerk: --withrottle: expected [HOST:]PORT\n");
        return std::nullopt;
    }
    return chosen;
}

} // namespace

int main(int argc, char* argv[]) {
    if (asksOnlyForText(argc, argv)) {
        const QCoreApplication text(argc, argv);
        nameApplication();
        parseOptions(text); // prints the help or the version and ends the program
        return 0;
    }
    QApplication app(argc, argv);
    nameApplication();
    QApplication::setWindowIcon(stellwerk::ui::applicationIcon());
    const Options options = parseOptions(app);

    stellwerk::ui::Translations translations;
    translations.select(stellwerk::ui::LanguageSettings::load());
    // The program's own station is the embedded simulated CS2, handed to the UI through the connection.
    stellwerk::connection::ConnectionSettings connectionSettings;
    // Where its trains stand is what a real station cannot say: it goes to the railway beside the
    // connection (the book outlives the station).
    stellwerk::model::OccupantBook demoOccupants;
    connectionSettings.localStation = [&demoOccupants] { return embeddedStation(demoOccupants); };
    // The MS1 handhelds' stacks and names, kept across runs in the program's settings.
    stellwerk::mcanhandhelds::SettingsHandheldBook handheldBook(QCoreApplication::organizationName(),
                                                                QCoreApplication::applicationName());
    connectionSettings.handhelds.book = &handheldBook;
    // The OpenRailCAN central and the RO modules, and what of the layout they switch and light (the
    // embedded station brings its own demo devices).
    QSettings deviceFile(QCoreApplication::organizationName(), QCoreApplication::applicationName());
    connectionSettings.devices = stellwerk::connection::DeviceSettings::load(deviceFile);
    connectionSettings.localStationDevices = stellwerk::connection::DeviceSettings::embeddedDemo();
    StationConnection connection{std::move(connectionSettings)}; // outlives the railway and the window
    stellwerk::model::LayoutInUse layout; // the station's download, or a folder the user opened
    // A railway model per session, bound to the handhelds and devices, and the layout in use it was loaded
    // with. The devices' bindings are read anew for every railway: the Devices panel may have changed them.
    stellwerk::binding::RailwayBinding railways(connection, &layout);
    railways.bindDevices([&connection, &deviceFile] {
        return connection.devices().onLocalStation() ? stellwerk::model::DeviceBindings::demo()
                                                     : stellwerk::model::DeviceBindings::load(deviceFile);
    });
    QObject::connect(
        &railways, &stellwerk::binding::RailwayBinding::railwayChanged, &railways,
        [&demoOccupants](stellwerk::model::Railway* railway) { demoOccupants.setRailway(railway); });
    // Automatic operation on the railway and the layout in use, with the book of trains kept beside the
    // layout (a station's in the program's data folder, by the station's address).
    stellwerk::operation::Operation::Options operationOptions;
    operationOptions.dataDir =
        QStandardPaths::writableLocation(QStandardPaths::AppDataLocation).toStdString();
    stellwerk::operation::Operation operation(layout, operationOptions);
    operation.setStationName([&connection] { return connection.address().toStdString(); });
    QObject::connect(&railways, &stellwerk::binding::RailwayBinding::railwayChanged, &operation,
                     &stellwerk::operation::Operation::setRailway);
    // The phones' servers (Z21, WiThrottle), off unless the settings or the flags switch them on.
    const auto phoneChoice = phoneSettings(deviceFile, options);
    if (!phoneChoice)
        return 1;
    stellwerk::phones::PhoneServers phones(deviceFile);
    for (const QString& problem : phones.apply(*phoneChoice))
        std::fprintf(stderr, "stellwerk: cannot start the phone server: %s\n", qPrintable(problem));
    QObject::connect(&railways, &stellwerk::binding::RailwayBinding::railwayChanged, &phones,
                     &stellwerk::phones::PhoneServers::setRailway);
    stellwerk::ui::MainWindow window(translations);
    window.setPhoneServers(&phones);
    window.setConnection(&connection);
    window.setLayoutInUse(&layout);
    window.setOperation(&operation);
    QObject::connect(&operation, &stellwerk::operation::Operation::automationChanged, &window,
                     &stellwerk::ui::MainWindow::setAutomation);
    QObject::connect(&railways, &stellwerk::binding::RailwayBinding::railwayChanged, &window,
                     &stellwerk::ui::MainWindow::setRailway);
    if (!options.captureFile.isEmpty()) {
        if (const QString error = window.frameDecoder()->loadCapture(options.captureFile); !error.isEmpty()) {
            std::fprintf(stderr, "stellwerk: %s\n", qPrintable(error));
            return 1;
        }
        window.workspace()->showPanel(window.frameDecoder()); // show what was asked for
    }
    if (!options.panel.isEmpty() && !window.workspace()->showPanel(options.panel)) {
        std::fprintf(stderr, "stellwerk: there is no panel \"%s\"\n", qPrintable(options.panel));
        return 1;
    }
    if (options.size.isEmpty()) {
        window.showAtStart();
    } else {
        window.resize(options.size);
        window.show();
    }
    if (!options.screenshotFile.isEmpty() || options.reportGeometry)
        reportAndQuit(window, connection, options);
    QTimer::singleShot(0, &connection, [&connection, &options] {
        connection.connectTo(options.stationUrl, options.furtherBuses);
    });
    return QApplication::exec();
}
