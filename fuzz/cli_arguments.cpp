// The words the CLI reads from its command line: `encode NAME key=value...` and the locomotive,
// accessory, direction, speed, function, position and UID arguments of the drive commands.
// Invariants: a message built from arguments that decodes encodes to the same frame again (an encoded
// message decodes to itself); a locomotive or accessory written back by the CLI reads as the same
// Loc-ID; every number read is inside its documented range.
#include "FuzzSupport.h"
#include "LocArgument.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Fields.h"

#include <vector>

using namespace stellwerk;

namespace {

std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t end = text.find('\n'); end != std::string_view::npos; end = text.find('\n', start)) {
        parts.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    parts.emplace_back(text.substr(start));
    return parts;
}

void checkEncode(std::uint8_t choice, const std::vector<std::string>& lines) {
    const auto names = cs2::messageNames();
    std::vector<cs2::KeyValue> arguments;
    for (const std::string& line : lines)
        if (const auto equals = line.find('='); equals != std::string::npos)
            arguments.emplace_back(line.substr(0, equals), line.substr(equals + 1));
    const auto message = cs2::buildMessage(names[choice % names.size()], arguments);
    if (!message)
        return;
    const can::CanFrame frame = cs2::encode(*message);
    const auto decoded = cs2::decode(frame);
    if (!decoded)
        return; // `encode` reports this as an error, with the decoder's reason
    fuzz::check(cs2::encode(*decoded) == frame, "an encoded message does not decode to itself",
                can::formatDocument(frame));
}

void checkWords(const std::string& text) {
    if (const auto loco = cli::parseLocomotive(text)) {
        const auto again = cli::parseLocomotive(cli::locomotiveText(*loco));
        fuzz::check(again && *again == *loco, "a locomotive written back reads differently", text);
    }
    if (const auto article = cli::parseAccessory(text)) {
        const auto again = cli::parseAccessory(cli::accessoryText(*article));
        fuzz::check(again && *again == *article, "an accessory written back reads differently", text);
    }
    if (const auto direction = cli::parseDirection(text)) {
        const auto again = cli::parseDirection(cli::directionText(std::uint8_t(*direction)));
        fuzz::check(again && *again == *direction, "a direction written back reads differently", text);
    }
    if (const auto speed = cli::parseSpeed(text))
        fuzz::check(*speed <= 1000, "a speed above 1000 was accepted", text);
    if (const auto function = cli::parseFunctionNumber(text))
        fuzz::check(*function <= 31, "a function above 31 was accepted", text);
    cli::parsePosition(text);
    cli::parseOnOff(text);
    cli::parseUid(text);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 1024)
        return -1;
    fuzz::FuzzInput input(data, size);
    const std::uint8_t choice = input.byte();
    const auto lines = splitLines(input.restText());
    checkEncode(choice, lines);
    for (const std::string& line : lines)
        checkWords(line);
    return 0;
}
