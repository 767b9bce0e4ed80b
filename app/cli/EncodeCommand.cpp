#include "EncodeCommand.h"

#include "OrcEncode.h"
#include "RoCli.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Fields.h"
#include "cs2/FrameReport.h"

#include <ostream>

namespace stellwerk::cli {
namespace {

// The hash used when none is given: the one in every example of the protocol document.
constexpr const char* DefaultHash = "0x4711";

void printNames(std::ostream& out) {
    out << "Message names:\n";
    for (auto name : cs2::messageNames())
        out << "  " << name << '\n';
    out << "Envelope keys for every message: prio=0..15 response=true|false hash=0x4711 (default) packet=N\n";
    out << "RO modules: ro.write|ro.read width=bit|byte|word|long address=N job=N [value=N] [size=4|8] "
           "[id=N [standard=true]]\n";
}

} // namespace

int runEncode(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    if (arguments.empty() || arguments[0] == "--list" || arguments[0] == "--help") {
        if (arguments.empty())
            err << "usage: stellwerk-cli encode <name> key=value ...\n";
        printNames(arguments.empty() ? err : out);
        printOrcNames(arguments.empty() ? err : out);
        return arguments.empty() ? 2 : 0;
    }
    if (arguments[0].starts_with("orc."))
        return runOrcEncode(arguments, out, err);
    if (arguments[0].starts_with("ro."))
        return runRoEncode(arguments, out, err);

    std::vector<cs2::KeyValue> keyValues;
    bool hasHash = false;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        const auto equals = arguments[i].find('=');
        if (equals == std::string::npos || equals == 0) {
            err << "stellwerk-cli encode: '" << arguments[i] << "' is not key=value\n";
            return 2;
        }
        const std::string key = arguments[i].substr(0, equals);
        hasHash = hasHash || key == "hash" || key == "packet";
        keyValues.emplace_back(key, arguments[i].substr(equals + 1));
    }
    if (!hasHash)
        keyValues.emplace_back("hash", DefaultHash);

    const auto message = cs2::buildMessage(arguments[0], keyValues);
    if (!message) {
        err << "stellwerk-cli encode: " << message.error() << '\n';
        return 1;
    }
    const can::CanFrame frame = cs2::encode(*message);
    const cs2::FrameReport check(frame);
    if (!check.ok()) {
        err << "stellwerk-cli encode: " << arguments[0] << ": " << check.result().error().message() << '\n';
        return 1;
    }
    out << "document: " << can::formatDocument(frame) << '\n';
    out << "candump:  " << can::formatCandump(frame) << '\n';
    out << "network:  " << can::formatNetwork(frame) << '\n';
    return 0;
}

} // namespace stellwerk::cli
