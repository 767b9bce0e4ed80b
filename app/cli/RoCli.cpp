#include "RoCli.h"

#include "CliNumber.h"
#include "can/FrameText.h"
#include "ro/Codec.h"

#include <charconv>
#include <map>

namespace stellwerk::cli {
namespace {

using KeyValues = std::map<std::string, std::string, std::less<>>;

// A number key within `max`; the error names the key and what it got.
Expected<std::uint32_t, std::string> numberOf(const KeyValues& keys, std::string_view key, std::uint32_t max,
                                              std::optional<std::uint32_t> fallback = std::nullopt) {
    const auto found = keys.find(key);
    if (found == keys.end()) {
        if (fallback)
            return *fallback;
        return std::string(key) + "= is missing";
    }
    const auto number = parseNumber(found->second);
    if (!number || *number > max)
        return std::string(key) + "=" + found->second + " is not a number from 0 to " + std::to_string(max);
    return *number;
}

Expected<KeyValues, std::string> keyValuesOf(const std::vector<std::string>& arguments) {
    static const std::vector<std::string_view> known = {"width", "address", "job",     "value",
                                                        "size",  "id",      "standard"};
    KeyValues keys;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        const auto equals = arguments[i].find('=');
        if (equals == std::string::npos || equals == 0)
            return "'" + arguments[i] + "' is not key=value";
        const std::string key = arguments[i].substr(0, equals);
        if (std::find(known.begin(), known.end(), key) == known.end())
            return "unknown key " + key + " (width, address, job, value, size, id, standard)";
        keys[key] = arguments[i].substr(equals + 1);
    }
    return keys;
}

Expected<ro::Request, std::string> requestOf(const std::string& name, const KeyValues& keys) {
    ro::Request request;
    request.kind = name == "ro.write" ? ro::Request::Kind::Write : ro::Request::Kind::Read;
    const auto width = keys.find("width");
    if (width == keys.end() || !ro::widthFromName(width->second, request.width))
        return std::string("width= must be bit, byte, word or long");
    const auto address = numberOf(keys, "address", 0xFFFF);
    const auto job = numberOf(keys, "job", 0xFF);
    if (!address || !job)
        return !address ? address.error() : job.error();
    request.address = std::uint16_t(*address);
    request.job = std::uint8_t(*job);
    if (!request.isWrite())
        return keys.contains("value")
                   ? Expected<ro::Request, std::string>("a read carries no value= (004 §3.2.5)")
                   : Expected<ro::Request, std::string>(request);
    const auto value = numberOf(keys, "value", ro::maxValue(request.width));
    if (!value)
        return value.error() + " (" + std::string(ro::widthName(request.width)) + " write)";
    request.value = *value;
    return request;
}

std::string payloadText(const ro::Payload& payload) {
    static constexpr char digits[] = "0123456789ABCDEF";
    std::string text;
    for (const std::uint8_t byte : payload.span())
        text += std::string(text.empty() ? "" : " ") + digits[byte >> 4] + digits[byte & 15];
    return text;
}

int printRequest(const ro::Request& request, const KeyValues& keys, std::ostream& out, std::ostream& err) {
    const auto size = numberOf(keys, "size", 8, 8);
    if (!size || (*size != 4 && *size != 8)) {
        err << "stellwerk-cli encode: size= must be 4 or 8\n";
        return 2;
    }
    const ro::Payload payload = ro::encode(request, ro::ReadRequestSize(*size));
    out << "payload:  " << payloadText(payload) << '\n';
    if (!keys.contains("id"))
        return 0;
    const bool standard = keys.contains("standard") && keys.at("standard") == "true";
    const auto id =
        numberOf(keys, "id", standard ? can::CanFrame::StandardIdMask : can::CanFrame::ExtendedIdMask);
    if (!id) {
        err << "stellwerk-cli encode: " << id.error() << '\n';
        return 2;
    }
    const can::CanFrame frame = ro::frameOf(*id, !standard, payload);
    out << "document: " << can::formatDocument(frame) << '\n';
    out << "candump:  " << can::formatCandump(frame) << '\n';
    return 0;
}

} // namespace

int runRoEncode(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
    if (arguments[0] != "ro.write" && arguments[0] != "ro.read") {
        err << "stellwerk-cli encode: " << arguments[0] << ": RO messages are ro.write and ro.read\n";
        return 1;
    }
    const auto keys = keyValuesOf(arguments);
    if (!keys) {
        err << "stellwerk-cli encode: " << keys.error() << '\n';
        return 2;
    }
    const auto request = requestOf(arguments[0], *keys);
    if (!request) {
        err << "stellwerk-cli encode: " << arguments[0] << ": " << request.error() << '\n';
        return 1;
    }
    return printRequest(*request, *keys, out, err);
}

Expected<ro::FrameIds, std::string> parseRoModule(std::string_view text) {
    ro::FrameIds ids;
    bool request = false, answer = false;
    while (!text.empty()) {
        const std::size_t comma = text.find(',');
        const std::string_view part = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        const auto number = parseNumber(part.substr(std::min(part.size(), part.find('=') + 1)));
        if (part == "std")
            ids.extended = false;
        else if (part.starts_with("req=") && number)
            ids.request = *number, request = true;
        else if (part.starts_with("resp=") && number)
            ids.answer = *number, answer = true;
        else
            return "--ro-module: '" + std::string(part) + "' is none of req=ID, resp=ID, std";
    }
    if (!request || !answer)
        return std::string("--ro-module needs req=ID,resp=ID[,std]");
    ro::RoProfile profile;
    profile.ids = ids;
    if (const std::string problem = profile.problem(); !problem.empty())
        return "--ro-module: " + problem;
    return ids;
}

} // namespace stellwerk::cli
