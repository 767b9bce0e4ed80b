#include "DecodeCommand.h"

#include "bus/FrameClassifier.h"
#include "cs2/FrameReport.h"
#include "cs2/FrameText.h"
#include "cs2/JsonText.h"

#include <istream>
#include <ostream>

namespace stellwerk::cli {
namespace {

// Decodes and prints one input line; returns false when the frame was unreadable or invalid.
class FramePrinter {
public:
    FramePrinter(bool json, std::ostream& out, std::ostream& err) : json_(json), out_(out), err_(err) {}

    bool print(const std::string& input, std::size_t lineNumber) {
        const auto parsed = cs2::parseFrame(input);
        if (!parsed) {
            reportUnreadable(input, lineNumber, parsed.error());
            return false;
        }
        if (bus::classify(parsed->frame, profile_) == bus::Protocol::Foreign) {
            printForeign(parsed->frame);
            return true;
        }
        const cs2::FrameReport report(parsed->frame);
        out_ << (json_ ? withProtocol(report.json(), bus::Protocol::Cs2) : report.text()) << '\n';
        return report.ok();
    }

private:
    // {"protocol":"cs2", followed by the report's own keys.
    static std::string withProtocol(const std::string& json, bus::Protocol protocol) {
        return "{\"protocol\":\"" + std::string(bus::protocolName(protocol)) + "\"," + json.substr(1);
    }

    // A frame no protocol of the bus claims (today: a standard 11-bit frame) is shown, not decoded.
    void printForeign(const can::CanFrame& frame) {
        const std::string candump = cs2::formatCandump(frame);
        const std::string id = candump.substr(0, candump.find('#'));
        const std::string data = candump.substr(candump.find('#') + 1);
        if (json_)
            out_ << "{\"protocol\":\"foreign\",\"id\":\"" << id
                 << "\",\"extended\":" << (frame.extended ? "true" : "false") << ",\"dlc\":" << int(frame.dlc)
                 << ",\"data\":\"" << data << "\"}\n";
        else
            out_ << cs2::formatDocument(frame) << "  foreign " << (frame.extended ? "29-bit" : "11-bit")
                 << " frame (no protocol of a CS2 bus)\n";
    }

    void reportUnreadable(const std::string& input, std::size_t lineNumber, const std::string& error) {
        if (json_)
            out_ << "{\"input\":" << cs2::jsonQuoted(input) << ",\"error\":" << cs2::jsonQuoted(error)
                 << "}\n";
        else
            err_ << "stellwerk-cli decode: line " << lineNumber << ": " << error << ": " << input << '\n';
    }

    bool json_;
    bus::BusProfile profile_ = bus::BusProfile::centralStation();
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
    for (const auto& argument : arguments) {
        if (argument == "--json") {
            json = true;
        } else if (argument.size() > 2 && argument.rfind("--", 0) == 0) {
            err << "stellwerk-cli decode: unknown option " << argument << '\n';
            return 2;
        } else {
            frames.push_back(argument);
        }
    }

    FramePrinter printer(json, out, err);
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
