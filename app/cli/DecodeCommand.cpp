#include "DecodeCommand.h"

#include "RoCli.h"
#include "bus/BusContext.h"
#include "can/FrameText.h"
#include "cs2/JsonText.h"

#include <istream>
#include <ostream>

namespace stellwerk::cli {
namespace {

// Decodes and prints one input line; returns false when the frame was unreadable or invalid. The lines of
// one run are one bus: what earlier frames revealed (an MS1's handles and names) names the later ones.
class FramePrinter {
public:
    FramePrinter(bool json, bus::BusProfile profile, std::ostream& out, std::ostream& err)
        : json_(json), profile_(std::move(profile)), out_(out), err_(err) {}

    bool print(const std::string& input, std::size_t lineNumber) {
        const auto parsed = can::parseFrame(input);
        if (!parsed) {
            reportUnreadable(input, lineNumber, parsed.error());
            return false;
        }
        // A frame no protocol of the bus claims is shown, not decoded, and is no error.
        const bus::FrameDescription description = context_.read(parsed->frame, profile_);
        out_ << (json_ ? description.json() : description.text()) << '\n';
        return description.decoded() || description.protocol() == bus::Protocol::Foreign;
    }

private:
    void reportUnreadable(const std::string& input, std::size_t lineNumber, const std::string& error) {
        if (json_)
            out_ << "{\"input\":" << cs2::jsonQuoted(input) << ",\"error\":" << cs2::jsonQuoted(error)
                 << "}\n";
        else
            err_ << "stellwerk-cli decode: line " << lineNumber << ": " << error << ": " << input << '\n';
    }

    bool json_;
    bus::BusProfile profile_;
    bus::BusContext context_;
    std::ostream& out_;
    std::ostream& err_;
};

bool isSkippable(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    return first == std::string::npos || line[first] == '#';
}

} // namespace

int runDecode(const std::vector<std::string>& arguments, std::istream& in, std::ostream& out,
              std::ostream& err) {
    bool json = false;
    std::vector<std::string> frames;
    bus::BusProfile profile = bus::BusProfile::centralStation();
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        if (argument == "--json") {
            json = true;
        } else if (argument == "--ro-module") {
            const auto ids = parseRoModule(i + 1 < arguments.size() ? arguments[++i] : std::string());
            if (!ids) {
                err << "stellwerk-cli decode: " << ids.error() << '\n';
                return 2;
            }
            profile.addRoModule(*ids);
        } else if (argument.size() > 2 && argument.rfind("--", 0) == 0) {
            err << "stellwerk-cli decode: unknown option " << argument << '\n';
            return 2;
        } else {
            frames.push_back(argument);
        }
    }

    FramePrinter printer(json, std::move(profile), out, err);
    bool allGood = true;
    if (!frames.empty()) {
        for (std::size_t i = 0; i < frames.size(); ++i)
            allGood = printer.print(frames[i], i + 1) && allGood;
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
