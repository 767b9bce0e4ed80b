#include "StationCommand.h"

#include "AutoCommand.h"
#include "DeviceCommands.h"
#include "DriveCommands.h"
#include "HandheldCommand.h"
#include "OrcCommand.h"
#include "ResyncCommand.h"
#include "RoCommand.h"
#include "ServeCommand.h"
#include "StationClient.h"
#include "TransferCommands.h"

#include <ostream>

namespace stellwerk::cli {
namespace {

ParsedJob parseCommand(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    const std::string& command = arguments[1];
    const std::vector<std::string> rest(arguments.begin() + 2, arguments.end());
    if (auto job = parseDriveCommand(command, rest, out, err))
        return std::move(*job);
    if (auto job = parseDeviceCommand(command, rest, out, err))
        return std::move(*job);
    if (auto job = parseTransferCommand(command, rest, out, err))
        return std::move(*job);
    if (auto job = parseResyncCommand(command, rest, out, err))
        return std::move(*job);
    if (auto job = parseHandheldCommand(command, rest, out, err))
        return std::move(*job);
    if (auto job = parseRoCommand(command, rest, out, err))
        return std::move(*job);
    if (auto job = parseOrcCommand(command, rest, out, err))
        return std::move(*job);
    if (auto job = parseAutoCommand(command, rest, out, err))
        return std::move(*job);
    if (auto job = parseServeCommand(command, rest, out, err))
        return std::move(*job);
    return "unknown station command '" + command + "'";
}

} // namespace

const char* stationUsage() {
    return "  stellwerk-cli --station URL COMMAND      talk to a command station; exit status 0 "
           "acknowledged,\n"
           "                1 not acknowledged (rejected, timed out), 2 usage error, 3 cannot open URL\n"
           "    URL: udp://host[:port][?listen=port]  (sends to port, default 15731; receives on listen,\n"
           "                                          default 15730)\n"
           "         tcp://host[:port]                (default 15731)\n"
           "         can://plugin/interface[?bitrate=n] (a QCanBus device, e.g. can://socketcan/can0)\n"
           "    ping                               list the devices (UID, version, type)\n"
           "    stop | go | halt [UID]             track power off / on, every loco to speed 0\n"
           "    speed LOC 0-1000                   LOC: mfx:5, dcc:3, mm2:72 or a Loc-ID (0x4005)\n"
           "    direction LOC forward|backward|toggle\n"
           "    function LOC 0-31 on|off\n"
           "    switch ADDR POSITION               ADDR: keyboard number 1.. (mm2), dcc:N, or 0x3004;\n"
           "                                       POSITION: 0-255, red|round, green|straight, yellow, "
           "white\n"
           "    download KEY [QUALIFIER] [-o FILE] a config file (loks, mags, fs, gbs, gbs-N, ...)\n"
           "    status [UID]                       readings (name, value, unit) of the device(s); without\n"
           "                                       UID, devices with no status data (PC programs) are\n"
           "                                       named and skipped: exit 0 when every device with status\n"
           "                                       data was read, 1 when a reading failed or none had any\n"
           "    monitor [--json] [--count N]       print every frame until N frames or Ctrl-C\n"
           "    resync [--stop]                    bring the layout back in step: every loco gets the speed\n"
           "                                       the station confirmed (--stop: 0), every state is read\n"
           "                                       again and each loco printed; exit 1 when one went\n"
           "                                       unanswered\n"
           "    handhelds [--json] [--master|--watch] [--seconds N]\n"
           "                                       be the M-CAN master of the MS1 handhelds on the bus (not\n"
           "                                       beside a Central Station, which is their master; "
           "--master:\n"
           "                                       always; --watch: only watch) and print one line per "
           "event\n"
           "                                       (login, upgrade-done, loco-taken/released, speed, "
           "function,\n"
           "                                       stop, go, silent, lost) until Ctrl-C or N seconds\n"
           "    ro --module req=ID,resp=ID[,std] [--json] [--timeout MS] ACTION\n"
           "                                       an RO relay/IO module on the bus (relays at 0x0000, "
           "inputs\n"
           "                                       at 0x0020 as in stellwerk-sim): read ADDRESS WIDTH, "
           "write\n"
           "                                       ADDRESS WIDTH VALUE, switch RELAY on|off, watch "
           "[--seconds\n"
           "                                       N]; exit 0 done, 1 no answer, 4 refused (0xFE)\n"
           "    orc [--json] [--seconds N] ACTION  Stellwerk as the OpenRailCAN central on the bus: find\n"
           "                                       (devices that answer within N s, default 1), switch\n"
           "                                       TARGET POS (dekoder schalten, waits for the ack), watch;\n"
           "                                       exit 0 a device answered, 1 none did\n"
           "    auto run [--layout DIR] --place LOC=CONTACT[:END]... [--schedule FILE] [--seconds N] "
           "[--json]\n"
           "                                       run the placed trains automatically on the track graph "
           "of\n"
           "                                       the station's plan (or DIR's) for N s (default 60) or\n"
           "                                       until Ctrl-C, one line per event, then stop them and "
           "print\n"
           "                                       a summary; exit 0 when no fault occurred, 1 otherwise\n"
           "    serve [--z21 [HOST:]PORT] [--withrottle [HOST:]PORT] [--seconds N] [--json]\n"
           "                                       phones as throttles: the Z21 LAN server (Z21 app,\n"
           "                                       WLANmaus; port 21105) and the WiThrottle server\n"
           "                                       (Engine Driver, WiThrottle; port 12090) in front of the\n"
           "                                       station (neither given: Z21 only), one line per client\n"
           "                                       event until N s or Ctrl-C, then the locos its clients\n"
           "                                       drove are stopped\n";
}

int runStation(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    if (arguments.size() < 2) {
        err << "usage: stellwerk-cli --station URL COMMAND ...\n" << stationUsage();
        return UsageError;
    }
    const ParsedJob job = parseCommand(arguments, out, err);
    if (!job) {
        err << "stellwerk-cli: " << job.error() << '\n';
        return UsageError;
    }
    StationClient client(err);
    if (const int opened = client.connectTo(QString::fromStdString(arguments[0])); opened != 0)
        return opened;
    return client.run(*job);
}

} // namespace stellwerk::cli
