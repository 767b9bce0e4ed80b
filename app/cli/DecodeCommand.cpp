#include "DecodeCommand.h"

#include "RoCli.h"
#include "busreading/BusContext.h"
#include "can/FrameText.h"
#include "cs2/JsonText.h"

#include <istream>
#include <optional>
#include <ostream>

namespace stellwerk::cli {
namespace {

// Decodes and prints one input line; returns false when the frame was unreadable or invalid. The lines of
// one run are one bus: what earlier frames revealed (an MS1's handles and names) names the later ones.
class FramePrinter {
public:
    FramePrinter(bool json, std::ostream& out, std::ostream& err) : json_(json), out_(out), err_(err) {}

    // The bus the lines come from (`--protocol`); auto: a station's bus, where a frame that M-CAN cannot
    // read but OpenRailCAN can is shown as OpenRailCAN (the two overlap, ORC notes O26). The RO modules'
    // ids (`--ro-module`) are claimed first on any of them.
    bool chooseProtocol(const std::string& name, const std::vector<ro::FrameIds>& roModules) {
        orcFallback_ = name == "auto";
        if (name == "auto" || name == "mcan")
            profile_ = busreading::BusProfile::centralStation();
        else if (name == "cs2")
            profile_ = busreading::BusProfile{busreading::Protocol::Cs2};
        else if (name == "orc")
            profile_ = busreading::BusProfile::openRailCan();
        else
            return false;
        for (const ro::FrameIds& ids : roModules)
            profile_.addRoModule(ids);
        return true;
    }

    bool print(const std::string& input, std::size_t lineNumber) {
        const auto parsed = can::parseFrame(input);
        if (!parsed) {
            reportUnreadable(input, lineNumber, parsed.error());
            return false;
        }
        // A frame no protocol of the bus claims is shown, not decoded, and is no error.
        const busreading::FrameDescription description = describe(parsed->frame);
        out_ << (json_ ? description.json() : description.text()) << '\n';
        return description.decoded() || description.protocol() == busreading::Protocol::Foreign;
    }

private:
    busreading::FrameDescription describe(const can::CanFrame& frame) {
        busreading::FrameDescription description = context_.read(frame, profile_);
        if (!orcFallback_ || description.protocol() != busreading::Protocol::Mcan || description.decoded())
            return description;
        busreading::FrameDescription orc(frame, busreading::BusProfile::openRailCan());
        return orc.protocol() == busreading::Protocol::Orc && orc.decoded() ? orc : description;
    }

    void reportUnreadable(const std::string& input, std::size_t lineNumber, const std::string& error) {
        if (json_)
            out_ << "{\"input\":" << cs2::jsonQuoted(input) << ",\"error\":" << cs2::jsonQuoted(error)
                 << "}\n";
        else
            err_ << "stellwerk-cli decode: line " << lineNumber << ": " << error << ": " << input << '\n';
    }

    bool json_;
    busreading::BusProfile profile_ = busreading::BusProfile::centralStation();
    bool orcFallback_ = true;
    busreading::BusContext context_;
    std::ostream& out_;
    std::ostream& err_;
};

bool isSkippable(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    return first == std::string::npos || line[first] == '#';
}

struct DecodeOptions {
    bool json = false;
    std::string protocol = "auto";
    std::vector<ro::FrameIds> roModules;
    std::vector<std::string> frames;
};

// --json, --protocol NAME (or --protocol=NAME), --ro-module req=ID,resp=ID[,std] (repeatable) and the
// frames; empty after an unknown option or a module it cannot read.
std::optional<DecodeOptions> readOptions(const std::vector<std::string>& arguments, std::ostream& err) {
    DecodeOptions options;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        if (argument == "--json")
            options.json = true;
        else if (argument == "--protocol" && i + 1 < arguments.size())
            options.protocol = arguments[++i];
        else if (argument.rfind("--protocol=", 0) == 0)
            options.protocol = argument.substr(11);
        else if (argument == "--ro-module") {
            const auto ids = parseRoModule(i + 1 < arguments.size() ? arguments[++i] : std::string());
            if (!ids) {
                err << "stellwerk-cli decode: " << ids.error() << '\n';
                return std::nullopt;
            }
            options.roModules.push_back(*ids);
        } else if (argument.size() > 2 && argument.rfind("--", 0) == 0) {
            err << "stellwerk-cli decode: unknown option " << argument << '\n';
            return std::nullopt;
        } else
            options.frames.push_back(argument);
    }
    return options;
}

} // namespace

int runDecode(const std::vector<std::string>& arguments, std::istream& in, std::ostream& out,
              std::ostream& err) {
    const std::optional<DecodeOptions> options = readOptions(arguments, err);
    if (!options)
        return 2;
    FramePrinter printer(options->json, out, err);
    if (!printer.chooseProtocol(options->protocol, options->roModules)) {
        err << "stellwerk-cli decode: --protocol " << options->protocol << ": use auto, cs2, mcan or orc\n";
        return 2;
    }
    bool allGood = true;
    if (!options->frames.empty()) {
        for (std::size_t i = 0; i < options->frames.size(); ++i)
            allGood = printer.print(options->frames[i], i + 1) && allGood;
    } else {
        std::string line;
        for (std::size_t number = 1; std::getline(in, line); ++number)
            if (!isSkippable(line))
                allGood = printer.print(line, number) && allGood;
    }
    out.flush();
    return allGood ? 0 : 1;
}

} // namespace stellwerk::cli
