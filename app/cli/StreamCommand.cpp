#include "StreamCommand.h"

#include "CliNumber.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2config/ConfigStreamKeys.h"
#include "cs2config/ConfigStreamReceiver.h"
#include "cs2config/ConfigStreamRequestCollector.h"
#include "cs2config/ConfigStreamSender.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <istream>
#include <map>
#include <optional>
#include <ostream>
#include <set>

namespace stellwerk::cli {
namespace {

namespace fs = std::filesystem;
using cs2config::StreamOutcome;

constexpr const char* DecodeUsage = "usage: stellwerk-cli stream decode [FILE] [-d DIR]\n";
constexpr const char* EncodeUsage = "usage: stellwerk-cli stream encode FILE --key KEY [--follow-up TEXT] "
                                    "[--hash 0x4711] [--broadcast] [--notation document|candump]\n";

std::string hex16(std::uint16_t value) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "0x%04X", value);
    return buffer;
}

std::optional<std::uint16_t> parseHash(std::string_view text) {
    const auto value = parseNumber(text, 0xFFFF);
    return value ? std::optional(std::uint16_t(*value)) : std::nullopt;
}

bool isSkippable(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    return first == std::string::npos || line[first] == '#';
}

bool looksLikeText(const std::string& contents) {
    return contents.find('\0') == std::string::npos;
}

// ---- stream decode ------------------------------------------------------------------------------

// Follows the requests and streams of a capture, one receiver per hash, and stores every file.
class StreamExtractor {
public:
    StreamExtractor(fs::path directory, std::ostream& out, std::ostream& err)
        : directory_(std::move(directory)), out_(out), err_(err) {}

    void line(const std::string& text, std::size_t number) {
        const auto parsed = can::parseFrame(text);
        if (!parsed) {
            err_ << "stellwerk-cli stream decode: line " << number << ": " << parsed.error()
                 << " (skipped): " << text << '\n';
            return;
        }
        line_ = number;
        frame(parsed->frame);
    }

    void finish() {
        line_ = 0;
        for (auto& [hash, receiver] : receivers_)
            if (auto outcome = receiver.finish())
                report(*outcome);
    }

    bool allGood() const { return allGood_; }

private:
    void frame(const can::CanFrame& frame) {
        if (cs2::command(frame) == std::uint8_t(cs2::Command::ConfigDataRequest)) {
            if (const auto message = cs2::decode(frame))
                if (const auto request = requests_.feed(*message))
                    receivers_[request->hash].expectFile(request->request.key(), request->hash);
            return;
        }
        if (cs2::command(frame) == std::uint8_t(cs2::Command::ConfigDataStream))
            for (const auto& outcome : receivers_[cs2::hash(frame)].feed(frame))
                report(outcome);
    }

    void report(const StreamOutcome& outcome) {
        ++streams_;
        if (!outcome) {
            err_ << "stellwerk-cli stream decode: "
                 << (line_ ? "line " + std::to_string(line_) : "end of input") << ": stream " << streams_
                 << ": " << outcome.error().message << '\n';
            allGood_ = false;
            return;
        }
        const std::string name = fileName(*outcome);
        if (!write(name, outcome->contents))
            return;
        out_ << name << ": " << outcome->contents.size() << " bytes, CRC " << hex16(outcome->crc) << " ok, "
             << (outcome->compressed ? "compressed" : "plain") << ", "
             << (outcome->broadcast ? "broadcast from hash " : "to hash ") << hex16(outcome->hash) << '\n';
    }

    std::string fileName(const cs2config::ReceivedConfigFile& file) {
        std::string name = cs2config::fileNameForKey(file.key);
        if (name.empty())
            name = "stream-" + std::to_string(streams_) + (looksLikeText(file.contents) ? ".cs2" : ".bin");
        const auto dot = name.rfind('.');
        std::string unique = name;
        for (int n = 2; !used_.insert(unique).second; ++n)
            unique = name.substr(0, dot) + "-" + std::to_string(n) + name.substr(dot);
        return unique;
    }

    bool write(const std::string& name, const std::string& contents) {
        std::ofstream file(directory_ / name, std::ios::binary);
        file.write(contents.data(), std::streamsize(contents.size()));
        if (file)
            return true;
        err_ << "stellwerk-cli stream decode: cannot write " << (directory_ / name).string() << '\n';
        allGood_ = false;
        return false;
    }

    fs::path directory_;
    std::ostream& out_;
    std::ostream& err_;
    cs2config::ConfigRequestCollector requests_;
    std::map<std::uint16_t, cs2config::ConfigStreamReceiver> receivers_;
    std::set<std::string> used_;
    std::size_t streams_ = 0;
    std::size_t line_ = 0; // of the frame being handled; 0 at the end of the input
    bool allGood_ = true;
};

// What `stream decode` reads and where it writes.
struct DecodeOptions {
    std::optional<std::string> input;
    fs::path directory = ".";
};

std::optional<DecodeOptions> parseDecodeOptions(const std::vector<std::string>& arguments,
                                                std::ostream& err) {
    DecodeOptions options;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        if ((argument == "-d" || argument == "--directory") && i + 1 < arguments.size()) {
            options.directory = arguments[++i];
        } else if ((argument.size() > 1 && argument[0] == '-') || options.input) {
            err << "stellwerk-cli stream decode: unexpected argument '" << argument << "'\n" << DecodeUsage;
            return std::nullopt;
        } else {
            options.input = argument;
        }
    }
    return options;
}

int runDecode(const std::vector<std::string>& arguments, std::istream& stdinStream, std::ostream& out,
              std::ostream& err) {
    const auto options = parseDecodeOptions(arguments, err);
    if (!options)
        return 2;
    std::ifstream file;
    if (options->input && *options->input != "-") {
        file.open(*options->input);
        if (!file) {
            err << "stellwerk-cli stream decode: cannot read " << *options->input << '\n';
            return 1;
        }
    }
    std::error_code ec;
    fs::create_directories(options->directory, ec);
    StreamExtractor extractor(options->directory, out, err);
    std::istream& in = file.is_open() ? file : stdinStream;
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number)
        if (!isSkippable(line))
            extractor.line(line, number);
    extractor.finish();
    return extractor.allGood() ? 0 : 1;
}

// ---- stream encode ------------------------------------------------------------------------------

// What `stream encode` sends and how it prints the frames.
struct EncodeOptions {
    std::string input;
    std::string key;
    std::string followUp;
    std::uint16_t hash = 0x4711;
    bool broadcast = false;
    bool candump = false;
};

// Reads "--name value" options; returns the error text for a usage problem.
std::optional<std::string> parseEncodeOption(EncodeOptions& options,
                                             const std::vector<std::string>& arguments, std::size_t& i) {
    const std::string& option = arguments[i];
    if (option == "--broadcast") {
        options.broadcast = true;
        return std::nullopt;
    }
    if (i + 1 >= arguments.size())
        return "'" + option + "' needs a value";
    const std::string& value = arguments[++i];
    if (option == "--key")
        options.key = value;
    else if (option == "--follow-up")
        options.followUp = value;
    else if (option == "--hash" && parseHash(value))
        options.hash = *parseHash(value);
    else if (option == "--hash")
        return "'" + value + "' is not a 16-bit hash";
    else if (option == "--notation" && (value == "candump" || value == "document"))
        options.candump = value == "candump";
    else
        return "unknown option '" + option + " " + value + "'";
    return std::nullopt;
}

std::optional<EncodeOptions> parseEncodeOptions(const std::vector<std::string>& arguments,
                                                std::ostream& err) {
    EncodeOptions options;
    std::optional<std::string> problem;
    for (std::size_t i = 1; i < arguments.size() && !problem; ++i) {
        if (arguments[i].rfind("--", 0) == 0)
            problem = parseEncodeOption(options, arguments, i);
        else if (options.input.empty())
            options.input = arguments[i];
        else
            problem = "unexpected argument '" + arguments[i] + "'";
    }
    if (!problem && (options.input.empty() || options.key.empty()))
        problem = "FILE and --key are required";
    if (problem) {
        err << "stellwerk-cli stream encode: " << *problem << '\n' << EncodeUsage;
        return std::nullopt;
    }
    return options;
}

std::vector<can::CanFrame> framesFor(const EncodeOptions& options, const cs2config::ConfigRequest& request,
                                     const std::string& contents) {
    if (!options.broadcast)
        return cs2config::answerFrames(request, contents, options.hash);
    return cs2config::streamFrames(contents, cs2config::streamFormatForKey(options.key),
                                   cs2config::StreamAddress::broadcast(options.hash));
}

int runEncode(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    const auto options = parseEncodeOptions(arguments, err);
    if (!options)
        return 2;
    const auto request = cs2config::ConfigRequest::forKey(options->key, options->followUp);
    if (!request) {
        err << "stellwerk-cli stream encode: " << request.error() << '\n';
        return 2;
    }
    std::ifstream file(options->input, std::ios::binary);
    if (!file) {
        err << "stellwerk-cli stream encode: cannot read " << options->input << '\n';
        return 1;
    }
    const std::string contents{std::istreambuf_iterator<char>(file), {}};
    for (const auto& frame : framesFor(*options, *request, contents))
        out << (options->candump ? can::formatCandump(frame) : can::formatDocument(frame)) << '\n';
    return 0;
}

} // namespace

int runStream(const std::vector<std::string>& arguments, std::istream& in, std::ostream& out,
              std::ostream& err) {
    if (!arguments.empty() && arguments[0] == "decode")
        return runDecode(arguments, in, out, err);
    if (!arguments.empty() && arguments[0] == "encode")
        return runEncode(arguments, out, err);
    err << DecodeUsage << EncodeUsage;
    return 2;
}

} // namespace stellwerk::cli
