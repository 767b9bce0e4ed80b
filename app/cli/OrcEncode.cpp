#include "OrcEncode.h"

#include "can/FrameText.h"
#include "orc/Codec.h"
#include "orc/MessageBuilder.h"

#include <ostream>

namespace stellwerk::cli {

void printOrcNames(std::ostream& out) {
    out << "OpenRailCAN message names (keys for every one: prio=1..3 type=0..3 sender=BUSID):\n";
    for (const std::string_view name : orc::messageNames())
        if (name != orc::Unknown::name)
            out << "  " << name << "  " << orc::keysOf(name) << '\n';
}

int runOrcEncode(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    std::vector<orc::KeyValue> keyValues;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        const auto equals = arguments[i].find('=');
        if (equals == std::string::npos || equals == 0) {
            err << "stellwerk-cli encode: '" << arguments[i] << "' is not key=value\n";
            return 2;
        }
        keyValues.emplace_back(arguments[i].substr(0, equals), arguments[i].substr(equals + 1));
    }
    const auto message = orc::buildMessage(arguments[0], keyValues);
    if (!message) {
        err << "stellwerk-cli encode: " << message.error() << '\n';
        return 1;
    }
    const can::CanFrame frame = orc::encode(*message);
    const orc::Message check = orc::decode(frame);
    if (const auto* unknown = std::get_if<orc::Unknown>(&check)) {
        err << "stellwerk-cli encode: " << arguments[0] << ": " << unknown->why << '\n';
        return 1;
    }
    out << "document: " << can::formatDocument(frame) << '\n';
    out << "candump:  " << can::formatCandump(frame) << '\n';
    out << "network:  " << can::formatNetwork(frame) << '\n';
    return 0;
}

} // namespace stellwerk::cli
