#include "SimOptions.h"

#include <QCommandLineParser>

namespace stellwerk::simapp {

namespace {

struct Parser {
    QCommandLineParser parser;
    QCommandLineOption listen{"listen",
                              "Address to listen on (default 127.0.0.1; 0.0.0.0 for the whole network).",
                              "address", "127.0.0.1"};
    QCommandLineOption udpPort{"udp-port", "UDP port frames are received on (default 15731).", "port",
                               "15731"};
    QCommandLineOption udpReplyHost{
        "udp-reply-host",
        "Where UDP frames are sent (default 127.0.0.1; 255.255.255.255 broadcasts like a CS2).", "address",
        "127.0.0.1"};
    QCommandLineOption udpReplyPort{"udp-reply-port", "Port UDP frames are sent to (default 15730).", "port",
                                    "15730"};
    QCommandLineOption tcpPort{"tcp-port", "TCP port for 13-byte frame streams (default 15731).", "port",
                               "15731"};
    QCommandLineOption httpPort{
        "http-port", "HTTP port serving /config/<file> and /icons/<picture>.png (default 8080; 0: none).",
        "port", "8080"};
    QCommandLineOption can{"can",
                           "Also put the frames on a CAN interface (plugin:interface, e.g. socketcan:can0).",
                           "plugin:interface"};
    QCommandLineOption layout{
        "layout",
        "A CS2 config folder to serve instead of the demo layout; the trains run on its track plan.", "dir"};
    QCommandLineOption gleisbox{"gleisbox", "Also answer as a Gleisbox on the bus."};
    QCommandLineOption noTrains{"no-trains", "Locomotives do not move (no S88 events)."};
    QCommandLineOption tick{"tick", "Train movement step in milliseconds (default 100).", "ms", "100"};
    QCommandLineOption place{
        "place",
        "Put locomotive LOC (mfx:5, dcc:3, mm2:72 or a Loc-ID) in the block holding contact CONTACT, its "
        "front "
        "towards the block's end END (a or b, as 'stellwerk-cli layout graph' names them; b when left out), "
        "running forward that way. Repeatable; without it the demo's trains stand where they always do, and "
        "on "
        "another layout the first three locomotives are spread over the blocks.",
        "LOC=CONTACT[:END]"};
    QCommandLineOption ms1{
        "ms1",
        "Also put N simulated MS1 handhelds (M-CAN) on the station's bus, \"MS1 1\" to \"MS1 N\", "
        "which log in to the bus's M-CAN master and drive now and then (default 0, at most 31).",
        "N", "0"};
    QCommandLineOption noHandheldMaster{
        "no-handheld-master",
        "The station is not the M-CAN master of MS1 handhelds (as on a Gleisbox bus): it answers a ping as a "
        "Gleisbox, and a program on the bus (Stellwerk) may be their master."};

    QCommandLineOption ro{
        "ro",
        "Also put N simulated RO relay/IO modules on the station's bus: module n answers "
        "requests on 0x01FE0000+n on 0x01FF0000+n (29-bit), 16 relays at 0x0000, 16 inputs at "
        "0x0020, their change flags at 0x0022 (default 0).",
        "N", "0"};
    QCommandLineOption roLoseEvery{"ro-lose-every",
                                   "Every Nth answer of each RO module is lost (default 0: none).", "N", "0"};
    QCommandLineOption roDelay{"ro-delay", "RO modules answer this many milliseconds late (default 0).", "ms",
                               "0"};

    QCommandLineOption orcBooster{
        "orc-booster", "Also put a simulated OpenRailCAN booster (UID 0x3A2E0300, bus id 0x0300) on the "
                       "station's bus; it follows Alles EIN / Aus and keeps the loco commands it is sent."};
    QCommandLineOption orcOverloadAfter{
        "orc-overload-after",
        "The booster reports an overload on its port every MS milliseconds and clears it MS later "
        "(default 0: never).",
        "ms", "0"};
    QCommandLineOption orcOverloadPort{"orc-overload-port", "The booster port that overloads (default 1).",
                                       "port", "1"};
    QCommandLineOption orcDecoders{
        "orc-decoders",
        "Also put N simulated OpenRailCAN decoders with 8 outputs on the station's bus: decoder n has UID "
        "0x3A2E0100+n and asks for bus id 0x0100+n; Pos is its outputs, bit n = output n (default 0).",
        "N", "0"};
    QCommandLineOption orcEncoders{
        "orc-encoders",
        "Also put N simulated OpenRailCAN encoders with 32 inputs on the station's bus: encoder n has UID "
        "0x3A2E0200+n and asks for bus id 0x0200+n (default 0).",
        "N", "0"};
    QCommandLineOption orcEncoderToggle{
        "orc-encoder-toggle",
        "Every MS milliseconds one input of each encoder changes, inputs 0 to 31 in turn (default 2000; 0: "
        "never).",
        "ms", "2000"};

    QCommandLineOption orcThrottle{
        "orc-throttle",
        "Also put a simulated OpenRailCAN throttle (UID 0x3A2E0400, bus id 0x0400) on the station's bus that "
        "drives the loco with this Ziel-Id (e.g. 0x4001, mfx; 0x0018, MM; 0xC003, DCC) now and then, for a "
        "central that forwards it to the station.",
        "ziel-id"};
    QCommandLineOption orcThrottleEvery{
        "orc-throttle-every", "The throttle changes the speed every MS milliseconds (default 3000).", "ms",
        "3000"};

    Parser() {
        parser.setApplicationDescription(
            "A simulated Märklin Central Station 2 on UDP, TCP, HTTP and optionally CAN.");
        parser.addHelpOption();
        parser.addOptions({listen,
                           udpPort,
                           udpReplyHost,
                           udpReplyPort,
                           tcpPort,
                           httpPort,
                           can,
                           layout,
                           gleisbox,
                           noTrains,
                           tick,
                           place,
                           ms1,
                           noHandheldMaster,
                           ro,
                           roLoseEvery,
                           roDelay,
                           orcBooster,
                           orcOverloadAfter,
                           orcOverloadPort,
                           orcDecoders,
                           orcEncoders,
                           orcEncoderToggle,
                           orcThrottle,
                           orcThrottleEvery});
    }
};

std::optional<std::uint16_t> port(const QString& text) {
    bool ok = false;
    const uint value = text.toUInt(&ok);
    return ok && value <= 65535 ? std::optional<std::uint16_t>(std::uint16_t(value)) : std::nullopt;
}

// A whole number within [low, high] from an option, or why not.
std::optional<int> numberIn(const QCommandLineParser& parser, const QCommandLineOption& option, int low,
                            int high) {
    bool ok = false;
    const int value = parser.value(option).toInt(&ok);
    return ok && value >= low && value <= high ? std::optional(value) : std::nullopt;
}

std::optional<QString> readRo(const Parser& p, SimOptions& options) {
    const auto modules = numberIn(p.parser, p.ro, 0, MaximumRoModules);
    const auto loseEvery = numberIn(p.parser, p.roLoseEvery, 0, 1000);
    const auto delay = numberIn(p.parser, p.roDelay, 0, 10000);
    if (!modules)
        return "--ro: '" + p.parser.value(p.ro) + "' is not 0.." + QString::number(MaximumRoModules);
    if (!loseEvery)
        return "--ro-lose-every: '" + p.parser.value(p.roLoseEvery) + "' is not 0..1000";
    if (!delay)
        return "--ro-delay: '" + p.parser.value(p.roDelay) + "' is not 0..10000 milliseconds";
    options.roModules = *modules;
    options.roLoseEvery = *loseEvery;
    options.roDelay = std::chrono::milliseconds(*delay);
    return std::nullopt;
}

// What is wrong with an option's value: "--name: 'value' is not RANGE".
QString notIn(const QCommandLineParser& parser, const QCommandLineOption& option, const QString& range) {
    return "--" + option.names().front() + ": '" + parser.value(option) + "' is not " + range;
}

std::optional<QString> readOrcThrottle(const Parser& p, SimOptions& options) {
    const auto every = numberIn(p.parser, p.orcThrottleEvery, 1, 600000);
    if (!every)
        return notIn(p.parser, p.orcThrottleEvery, "1..600000 milliseconds");
    options.orcThrottleEvery = std::chrono::milliseconds(*every);
    if (!p.parser.isSet(p.orcThrottle))
        return p.parser.isSet(p.orcThrottleEvery)
                   ? std::optional<QString>("--orc-throttle-every needs --orc-throttle")
                   : std::nullopt;
    bool ok = false;
    const uint zielId = p.parser.value(p.orcThrottle).toUInt(&ok, 0);
    if (!ok || zielId > 0xFFFF)
        return notIn(p.parser, p.orcThrottle, "a Ziel-Id 0..0xFFFF");
    options.orcThrottleLoco = std::uint16_t(zielId);
    return std::nullopt;
}

// OpenRailCAN devices share the station's bus; M-CAN overlaps ORC there (docs/guide/openrailcan.md), so
// they exclude MS1 handhelds and the station is not the M-CAN master.
std::optional<QString> readOrc(const Parser& p, SimOptions& options) {
    constexpr int Longest = 600000;
    const auto overloadAfter = numberIn(p.parser, p.orcOverloadAfter, 0, Longest);
    const auto overloadPort = numberIn(p.parser, p.orcOverloadPort, 0, 254);
    const auto decoders = numberIn(p.parser, p.orcDecoders, 0, MaximumOrcDevices);
    const auto encoders = numberIn(p.parser, p.orcEncoders, 0, MaximumOrcDevices);
    const auto toggle = numberIn(p.parser, p.orcEncoderToggle, 0, Longest);
    const QString devices = "0.." + QString::number(MaximumOrcDevices);
    if (!overloadAfter)
        return notIn(p.parser, p.orcOverloadAfter, "0..600000 milliseconds");
    if (!overloadPort)
        return notIn(p.parser, p.orcOverloadPort, "a port 0..254");
    if (!decoders)
        return notIn(p.parser, p.orcDecoders, devices);
    if (!encoders)
        return notIn(p.parser, p.orcEncoders, devices);
    if (!toggle)
        return notIn(p.parser, p.orcEncoderToggle, "0..600000 milliseconds");
    if (const auto problem = readOrcThrottle(p, options))
        return problem;
    options.orcBooster = p.parser.isSet(p.orcBooster);
    if (!options.orcBooster && (p.parser.isSet(p.orcOverloadAfter) || p.parser.isSet(p.orcOverloadPort)))
        return QString("--orc-overload-after and --orc-overload-port need --orc-booster");
    options.orcOverloadAfter = std::chrono::milliseconds(*overloadAfter);
    options.orcOverloadPort = *overloadPort;
    options.orcDecoders = *decoders;
    options.orcEncoders = *encoders;
    options.orcEncoderToggle = std::chrono::milliseconds(*toggle);
    if (options.hasOrcDevices() && options.handhelds > 0)
        return QString("--ms1 and OpenRailCAN devices cannot share the station's bus: M-CAN overlaps "
                       "OpenRailCAN there");
    if (options.hasOrcDevices())
        options.handheldMaster = false;
    return std::nullopt;
}

std::optional<QString> readPlacements(const Parser& p, SimOptions& options) {
    for (const QString& text : p.parser.values(p.place)) {
        const auto placement = sim::parsePlacement(text.toStdString());
        if (!placement)
            return "--place: " + QString::fromStdString(placement.error());
        options.placements.push_back(*placement);
    }
    if (!options.placements.empty() && p.parser.isSet(p.noTrains))
        return QString("--place puts trains on the track, --no-trains keeps them off: choose one");
    return std::nullopt;
}

ParsedOptions failure(const QString& message) {
    return {std::nullopt, message, true};
}

// Reads the numbers and addresses; the first one that does not parse is the error.
std::optional<QString> readNetwork(const Parser& p, SimOptions& options) {
    const auto readPort = [&p](const QCommandLineOption& option,
                               std::uint16_t& target) -> std::optional<QString> {
        const std::optional<std::uint16_t> value = port(p.parser.value(option));
        if (!value)
            return "--" + option.names().front() + ": '" + p.parser.value(option) + "' is not a port number";
        target = *value;
        return std::nullopt;
    };
    const auto readAddress = [&p](const QCommandLineOption& option,
                                  QHostAddress& target) -> std::optional<QString> {
        if (!target.setAddress(p.parser.value(option)))
            return "--" + option.names().front() + ": '" + p.parser.value(option) + "' is not an IP address";
        return std::nullopt;
    };
    for (auto problem :
         {readAddress(p.listen, options.server.listenAddress),
          readAddress(p.udpReplyHost, options.server.udpReplyHost),
          readPort(p.udpPort, options.server.udpPort), readPort(p.udpReplyPort, options.server.udpReplyPort),
          readPort(p.tcpPort, options.server.tcpPort), readPort(p.httpPort, options.httpPort)})
        if (problem)
            return problem;
    if (options.server.udpReplyPort == 0)
        return QString("--udp-reply-port: frames cannot be sent to port 0");
    return std::nullopt;
}

std::optional<QString> readCan(const Parser& p, SimOptions& options) {
    if (!p.parser.isSet(p.can))
        return std::nullopt;
    const QString text = p.parser.value(p.can);
    const qsizetype colon = text.indexOf(':');
    if (colon <= 0 || colon == text.size() - 1)
        return "--can: '" + text + "' is not plugin:interface (e.g. socketcan:can0)";
    options.server.canBus =
        transport::CanBusSettings{text.left(colon), text.mid(colon + 1), std::nullopt, {}};
    return std::nullopt;
}

} // namespace

ParsedOptions parseSimOptions(const QStringList& arguments) {
    Parser p;
    if (!p.parser.parse(arguments))
        return failure(p.parser.errorText());
    if (p.parser.isSet("help"))
        return {std::nullopt, p.parser.helpText(), false};
    if (!p.parser.positionalArguments().isEmpty())
        return failure("unexpected argument '" + p.parser.positionalArguments().front() + "'");
    SimOptions options;
    if (const auto problem = readNetwork(p, options))
        return failure(*problem);
    if (const auto problem = readCan(p, options))
        return failure(*problem);
    bool ok = false;
    const int tick = p.parser.value(p.tick).toInt(&ok);
    if (!ok || tick < 1 || tick > 10000)
        return failure("--tick: '" + p.parser.value(p.tick) + "' is not 1..10000 milliseconds");
    options.tick = std::chrono::milliseconds(tick);
    const int handhelds = p.parser.value(p.ms1).toInt(&ok);
    if (!ok || handhelds < 0 || handhelds > MaximumHandhelds)
        return failure("--ms1: '" + p.parser.value(p.ms1) + "' is not 0.." +
                       QString::number(MaximumHandhelds));
    options.handhelds = handhelds;
    if (const auto problem = readRo(p, options))
        return failure(*problem);
    options.layoutDirectory = p.parser.value(p.layout);
    options.gleisbox = p.parser.isSet(p.gleisbox);
    options.handheldMaster = !p.parser.isSet(p.noHandheldMaster);
    if (const auto problem = readOrc(p, options))
        return failure(*problem);
    options.trains = !p.parser.isSet(p.noTrains);
    if (const auto problem = readPlacements(p, options))
        return failure(*problem);
    return {std::move(options), {}, false};
}

} // namespace stellwerk::simapp
