// stellwerk-cli: the protocol tools of Stellwerk for scripts and for debugging a bus.

#include "Cs2Command.h"
#include "DecodeCommand.h"
#include "EncodeCommand.h"
#include "LayoutCommand.h"
#include "StationCommand.h"
#include "StreamCommand.h"

#include <QCoreApplication>
#include <iostream>
#include <string>
#include <vector>

namespace {

void printUsage(std::ostream& out) {
    out << "stellwerk-cli " STELLWERK_VERSION " - Märklin CS2 protocol tools\n"
           "\n"
           "usage:\n"
           "  stellwerk-cli decode [--json] [FRAME ...]   decode CS2, M-CAN (MS1), OpenRailCAN and RO "
           "frames (arguments, "
           "or one per line\n"
           "                on stdin; the lines of one run are read as one bus, in order)\n"
           "                [--protocol=auto|cs2|mcan|orc]: the bus they come from (auto: a station's bus;\n"
           "                a frame M-CAN cannot read but OpenRailCAN can is shown as OpenRailCAN)\n"
           "                --ro-module req=ID,resp=ID[,std]: an RO module's frames on these ids "
           "(repeatable)\n"
           "  stellwerk-cli encode <name> key=value ...   build a frame and print it in all notations\n"
           "                (orc.<name>: an OpenRailCAN frame, e.g. orc.decoder.switch target=0x3005 "
           "position=1)\n"
           "  stellwerk-cli encode --list                 list the message names\n"
           "  stellwerk-cli stream decode [FILE] [-d DIR] store the config-data streams of a capture as "
           "files\n"
           "  stellwerk-cli stream encode FILE --key KEY [--follow-up TEXT] [--hash 0x4711] [--broadcast]\n"
           "                [--notation document|candump]  print the frames a CS2 sends for FILE\n"
           "  stellwerk-cli cs2 check FILE|DIR...         read .cs2 files, list every problem with its "
           "line;\n"
           "                a layout folder (DIR) is also checked as a whole: missing pages, tiles\n"
           "                sharing an article, tiles whose type or label disagree with their article\n"
           "  stellwerk-cli cs2 json FILE                 the file's locomotives, accessories, routes or "
           "track plan "
           "as JSON\n"
           "  stellwerk-cli cs2 format FILE [-o OUT]      write the file back through its typed model\n"
           "  stellwerk-cli layout graph DIR [--json]     the blocks, connections and problems the track "
           "plan of a\n"
           "                layout folder shows (exit 1 when it has no usable track plan)\n"
        << stellwerk::cli::stationUsage()
        << "\n"
           "FRAME notations:\n"
           "  document   00004711 5 00 00 00 00 00\n"
           "  candump    00004711#0000000000   or   (1700000000.000000) can0 00004711#0000000000\n"
           "  bracketed  can0  00004711   [5]  00 00 00 00 00\n"
           "  network    00004711050000000000000000   (13 bytes of the UDP/TCP gateway, 26 hex digits)\n"
           "\n"
           "Exit status: 0 all frames fine, 1 a frame (or stream) was invalid, 2 usage error.\n";
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    if (arguments.empty() || arguments[0] == "--help" || arguments[0] == "-h" || arguments[0] == "help") {
        printUsage(arguments.empty() ? std::cerr : std::cout);
        return arguments.empty() ? 2 : 0;
    }
    if (arguments[0] == "--version") {
        std::cout << "stellwerk-cli " STELLWERK_VERSION "\n";
        return 0;
    }
    const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
    if (arguments[0] == "decode")
        return stellwerk::cli::runDecode(rest, std::cin, std::cout, std::cerr);
    if (arguments[0] == "encode")
        return stellwerk::cli::runEncode(rest, std::cout, std::cerr);
    if (arguments[0] == "cs2")
        return stellwerk::cli::runCs2(rest, std::cout, std::cerr);
    if (arguments[0] == "layout")
        return stellwerk::cli::runLayout(rest, std::cout, std::cerr);
    if (arguments[0] == "stream")
        return stellwerk::cli::runStream(rest, std::cin, std::cout, std::cerr);
    if (arguments[0] == "--station") {
        QCoreApplication application(argc, argv); // the transports need an event loop
        return stellwerk::cli::runStation(rest, std::cout, std::cerr);
    }
    std::cerr << "stellwerk-cli: unknown command '" << arguments[0] << "'\n\n";
    printUsage(std::cerr);
    return 2;
}
