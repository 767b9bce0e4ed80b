// CS2 frame decode: 13 bytes in the network form, as any UDP or TCP peer may send them (shorter
// inputs are padded with zeros, so that the fuzzer spends no runs on other lengths).
// Invariants: a frame that decodes encodes back to the same bytes and decodes again to the same
// message; what describe() shows is enough to build the frame again (as `stellwerk-cli encode` does);
// the report's JSON is valid.
#include "FuzzSupport.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Fields.h"
#include "cs2/FrameReport.h"

#include <array>
#include <cstring>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::cs2;

namespace {

std::string argumentText(const Field& field) {
    switch (field.format) {
    case FieldFormat::Hex: {
        char buffer[24];
        std::snprintf(buffer, sizeof buffer, "0x%llX", static_cast<unsigned long long>(field.number));
        return buffer;
    }
    case FieldFormat::Bool:
        return field.number ? "true" : "false";
    case FieldFormat::Text:
        return field.text;
    case FieldFormat::Decimal:
        break;
    }
    return std::to_string(field.number);
}

void checkRebuild(const CanFrame& frame, const Message& message) {
    std::vector<KeyValue> arguments{{"prio", std::to_string(cs2::prio(frame))},
                                    {"response", cs2::isResponse(frame) ? "true" : "false"},
                                    {"hash", std::to_string(cs2::hash(frame))}};
    for (const Field& field : describe(message))
        if (!field.derived)
            arguments.emplace_back(std::string(field.key), argumentText(field));
    const auto rebuilt = buildMessage(messageName(message.body), arguments);
    fuzz::check(rebuilt.hasValue(), "the description of a decoded frame does not build a message",
                formatDocument(frame) + (rebuilt ? "" : ": " + rebuilt.error()));
    fuzz::check(encode(*rebuilt) == frame, "the frame built from the description differs",
                formatDocument(frame) + " -> " + formatDocument(encode(*rebuilt)));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > CanFrame::NetworkSize)
        return -1;
    std::array<std::uint8_t, CanFrame::NetworkSize> bytes{}; // shorter inputs: the rest is zero
    if (size > 0)
        std::memcpy(bytes.data(), data, size);
    const CanFrame frame = CanFrame::fromNetwork(bytes);
    const FrameReport report(frame);
    fuzz::check(fuzz::isJsonDocument(report.json(), false), "FrameReport::json() is not valid JSON",
                report.json());
    fuzz::check(cs2config::isValidUtf8(report.text()), "FrameReport::text() is not UTF-8", report.text());
    const auto decoded = decode(frame);
    if (!decoded)
        return 0;
    fuzz::check(frame.isWellFormed(), "a frame with DLC above 8 or id above 29 bits decoded",
                formatDocument(frame));
    const CanFrame encoded = encode(*decoded);
    fuzz::check(encoded == frame, "decode then encode changes the frame",
                formatDocument(frame) + " -> " + formatDocument(encoded));
    const auto again = decode(encoded);
    fuzz::check(again.hasValue() && encode(*again) == frame, "the encoded message does not decode to itself",
                formatDocument(frame));
    checkRebuild(frame, *decoded);
    return 0;
}
